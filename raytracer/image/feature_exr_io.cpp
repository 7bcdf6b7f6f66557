// The feature image as OpenEXR: the layout is documented in feature_exr.hpp.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "raytracer/image/atomic_file.hpp"
#include "raytracer/image/feature_exr.hpp"
#include "raytracer/image/image_formats.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace {
namespace {

// A channel: its name and where its floats are (base pointer and stride in bytes).
struct Plane {
    std::string name;
    const float* base;
    std::size_t stride;
};

std::vector<Plane> planes_of(const FeatureLayers& L) {
    std::vector<Plane> p;
    const char* rgb[3] = {"R", "G", "B"};
    const char* xyz[3] = {"X", "Y", "Z"};
    auto add = [&p](const std::string& prefix, const char* const* comps, const Image& im) {
        for (int c = 0; c < 3; ++c)
            p.push_back({prefix + comps[c], reinterpret_cast<const float*>(im.pixels.data()) + c, sizeof(glm::vec3)});
    };
    add("", rgb, L.color);
    add("Variance.", rgb, L.color_variance);
    add("Albedo.", rgb, L.albedo);
    add("Ns.", xyz, L.normal);
    add("P.", xyz, L.position);
    add("AlbedoVariance.", rgb, L.albedo_variance);
    add("NsVariance.", xyz, L.normal_variance);
    p.push_back({"PVariance.Z", L.depth_variance.data(), sizeof(float)});
    const char* half[2] = {"Even.", "Odd."};
    for (int h = 0; h < 2; ++h) {
        const std::string s = half[h];
        add(s, rgb, L.half_color[h]);
        add(s + "Albedo.", rgb, L.half_albedo[h]);
        add(s + "Ns.", xyz, L.half_normal[h]);
        add(s + "P.", xyz, L.half_position[h]);
    }
    return p;
}

}  // namespace

std::vector<std::string> feature_exr_channel_names() {
    FeatureLayers empty;
    std::vector<std::string> names;
    for (const Plane& p : planes_of(empty)) names.push_back(p.name);
    return names;
}

void write_feature_exr(const std::vector<FeatureSums>& sums, int width, int height, int spp, const std::filesystem::path& path) {
    const int w = width, h = height;
    if (w <= 0 || h <= 0) throw InputError("cannot write '" + path.string() + "': feature image is " + std::to_string(w) + "x" + std::to_string(h));
    // Blocks of about kBlockPixels pixels (whole rows): their 46 layers, 184 bytes a pixel, stay in
    // the cache between being computed and compressed, and a render's memory holds one block of
    // them rather than the whole image's (memory first touched is costly: docs/aovs.md, Cost).
    constexpr int kBlockPixels = 2048;
    const int block_rows = std::max(1, std::min(h, kBlockPixels / w));
    write_atomically(path, [&](const std::filesystem::path& temp) {
        try {
            Imf::Header header(w, h);
            // RLE (after OpenEXR's byte reordering and delta predictor, as ZIP does): the flat
            // layers (misses, walls of one albedo and normal) shrink, the noisy ones stay as they
            // are, which zlib barely deflates anyway. A 320x180 cornell-box feature image of 64
            // spp: 0.025 CPU-s and 4.5 MB against 0.072-0.090 s and 2.6 MB with ZIP at zlib's
            // fastest level, 3 % of the render's time for 40 % of the size (docs/aovs.md, Cost).
            header.compression() = Imf::RLE_COMPRESSION;
            header.insert(kExrSppAttribute, Imf::IntAttribute(spp));
            FeatureLayers block;
            for (const Plane& p : planes_of(block)) header.channels().insert(p.name, Imf::Channel(Imf::FLOAT));
            Imf::OutputFile file(temp.c_str(), header);
            for (int y0 = 0; y0 < h; y0 += block_rows) {
                const int rows = std::min(block_rows, h - y0);
                fill_feature_layers(sums.data() + static_cast<std::size_t>(y0) * w, w, rows, block);
                // Each slice's origin at row y0, where the lines OpenEXR writes next begin.
                Imf::FrameBuffer frame;
                for (const Plane& p : planes_of(block))
                    frame.insert(p.name, Imf::Slice::Make(Imf::FLOAT, p.base, Imath::V2i(0, y0), w, rows, p.stride,
                                                          p.stride * static_cast<std::size_t>(w)));
                file.setFrameBuffer(frame);
                file.writePixels(rows);
            }
        } catch (const std::exception& e) {
            throw InputError("cannot write '" + path.string() + "': " + reason_or(e.what(), "OpenEXR failed"));
        }
    });
}

}  // namespace sweeptrace
