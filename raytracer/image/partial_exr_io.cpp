// Farm parts as OpenEXR files: the layout is documented in partial_image.hpp.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <charconv>
#include <cstdio>
#include <limits>
#include <map>
#include <string>

#include "raytracer/image/atomic_file.hpp"
#include "raytracer/image/partial_image.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace {
namespace {

// 2: sweeptrace.adaptive and the count channel; 3: sweeptrace.aovs and aov.*; 4: the features'
// sums on the 2^-32 grid, 64 bits for albedo and normal (image/feature_sums.hpp); 5:
// sweeptrace.sampler (a format 4 part does not say which sampler drew its samples).
constexpr const char* kFormatVersion = "5";
constexpr int kWords = 4;                    // 32-bit words per 128-bit sum
constexpr int kSumChannels = 3 * kWords;     // sum.R.0 .. sum.B.3
const char* const kColor[3] = {"R", "G", "B"};
constexpr const char* kCountChannel = "count";  // adaptive parts only
constexpr int kMaxPartSide = 16384;              // film.width and film.height's limit (scene/film_limits.hpp)

std::string sum_channel(int color, int word) { return std::string("sum.") + kColor[color] + "." + std::to_string(word); }

// The attributes in a fixed order, values as text: what the checksum covers besides the sums.
std::map<std::string, std::string> attributes_of(const PartialImage& p) {
    return {{"sweeptrace.part", kFormatVersion},
            {"sweeptrace.sceneHash", p.id.scene_hash},
            {"sweeptrace.seed", std::to_string(p.id.seed)},
            {"sweeptrace.maxDepth", std::to_string(p.id.max_depth)},
            {"sweeptrace.accel", p.id.accel},
            {"sweeptrace.integrator", p.id.integrator},
            {"sweeptrace.sampler", p.id.sampler},
            {"sweeptrace.adaptive", p.id.adaptive},
            {"sweeptrace.aovs", p.id.aovs},
            {"sweeptrace.version", p.id.version},
            {"sweeptrace.spp", std::to_string(p.id.spp)},
            {"sweeptrace.samples", std::to_string(p.sample_begin) + ":" + std::to_string(p.sample_end)},
            {"sweeptrace.fractionBits", std::to_string(kSumFractionBits)}};
}

// FNV-1a 64: not cryptographic; it catches a file changed or damaged after it was written.
struct Fnv {
    std::uint64_t h = 0xcbf29ce484222325ull;
    void add(const void* data, std::size_t n) {
        const auto* b = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 0x100000001b3ull;
    }
    void add(const std::string& s) { add(s.data(), s.size() + 1); }  // with the NUL, so fields do not run together
};

std::string checksum_of(const PartialImage& p, const std::vector<std::uint32_t>& words, const std::vector<std::uint32_t>& counts,
                        const std::vector<std::uint32_t>& features) {
    Fnv f;
    for (const auto& [key, value] : attributes_of(p)) {
        f.add(key);
        f.add(value);
    }
    f.add(words.data(), words.size() * sizeof(std::uint32_t));
    f.add(counts.data(), counts.size() * sizeof(std::uint32_t));
    f.add(features.data(), features.size() * sizeof(std::uint32_t));
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(f.h));
    return buf;
}

std::vector<std::uint32_t> words_of(const std::vector<PixelSum>& sums) {
    std::vector<std::uint32_t> w(sums.size() * kSumChannels);
    for (std::size_t i = 0; i < sums.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const auto u = static_cast<SumUInt>(sums[i].rgb[c]);
            for (int k = 0; k < kWords; ++k) w[i * kSumChannels + c * kWords + k] = static_cast<std::uint32_t>(u >> (32 * k));
        }
    return w;
}

std::vector<PixelSum> sums_of(const std::vector<std::uint32_t>& w) {
    std::vector<PixelSum> sums(w.size() / kSumChannels);
    for (std::size_t i = 0; i < sums.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            SumUInt u = 0;
            for (int k = 0; k < kWords; ++k) u |= static_cast<SumUInt>(w[i * kSumChannels + c * kWords + k]) << (32 * k);
            sums[i].rgb[c] = static_cast<SumInt>(u);
        }
    return sums;
}

// A part's feature sums as stored: kFeatureWords per pixel (none without feature outputs).
std::vector<std::uint32_t> feature_words_of(const PartialImage& part) {
    std::vector<std::uint32_t> w(part.features.size() * kFeatureWords);
    for (std::size_t i = 0; i < part.features.size(); ++i) feature_to_words(part.features[i], w.data() + i * kFeatureWords);
    return w;
}

// An adaptive part's counts as stored (a uniform part: none).
std::vector<std::uint32_t> counts_of(const PartialImage& part) {
    if (part.id.adaptive == "off") return {};
    std::vector<std::uint32_t> c(part.sums.size());
    for (std::size_t i = 0; i < c.size(); ++i) c[i] = static_cast<std::uint32_t>(part.count(i));
    return c;
}

void write_exr_part(const PartialImage& part, const std::vector<std::uint32_t>& words, const std::vector<std::uint32_t>& counts,
                    const std::vector<std::uint32_t>& features, const std::filesystem::path& path) {
    const int w = part.id.width, h = part.id.height;
    Imf::Header header(w, h);
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const auto& [key, value] : attributes_of(part)) header.insert(key, Imf::StringAttribute(value));
    header.insert("sweeptrace.checksum", Imf::StringAttribute(checksum_of(part, words, counts, features)));
    const Image preview = part.mean();
    Imf::FrameBuffer frame;
    auto* rgb = const_cast<char*>(reinterpret_cast<const char*>(preview.pixels.data()));
    for (int c = 0; c < 3; ++c) {
        header.channels().insert(kColor[c], Imf::Channel(Imf::FLOAT));
        frame.insert(kColor[c], Imf::Slice(Imf::FLOAT, rgb + c * sizeof(float), sizeof(glm::vec3), sizeof(glm::vec3) * w));
    }
    auto* base = const_cast<char*>(reinterpret_cast<const char*>(words.data()));
    const std::size_t xs = kSumChannels * sizeof(std::uint32_t);
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < kWords; ++k) {
            header.channels().insert(sum_channel(c, k), Imf::Channel(Imf::UINT));
            frame.insert(sum_channel(c, k),
                         Imf::Slice(Imf::UINT, base + (c * kWords + k) * sizeof(std::uint32_t), xs, xs * w));
        }
    if (!counts.empty()) {
        header.channels().insert(kCountChannel, Imf::Channel(Imf::UINT));
        frame.insert(kCountChannel, Imf::Slice(Imf::UINT, const_cast<char*>(reinterpret_cast<const char*>(counts.data())),
                                               sizeof(std::uint32_t), sizeof(std::uint32_t) * w));
    }
    if (!features.empty()) {
        const std::vector<std::string>& names = feature_word_names();
        auto* fb = const_cast<char*>(reinterpret_cast<const char*>(features.data()));
        const std::size_t fs = kFeatureWords * sizeof(std::uint32_t);
        for (int k = 0; k < kFeatureWords; ++k) {
            header.channels().insert(names[static_cast<std::size_t>(k)], Imf::Channel(Imf::UINT));
            frame.insert(names[static_cast<std::size_t>(k)], Imf::Slice(Imf::UINT, fb + k * sizeof(std::uint32_t), fs, fs * w));
        }
    }
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(h);
}

std::string attribute(const Imf::Header& header, const std::string& key, const std::string& file) {
    const auto* a = header.findTypedAttribute<Imf::StringAttribute>(key);
    if (!a) throw InputError("'" + file + "': not a sweeptrace part (no " + key + " attribute)");
    return a->value();
}

template <class T = long long>
T number(const std::string& text, const std::string& key, const std::string& file) {
    T v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size())
        throw InputError("'" + file + "': attribute " + key + " is '" + text + "', not a number");
    return v;
}

// The identity and range from the header; the sums are read by the caller.
PartialImage header_part(const Imf::Header& hd, const std::string& file) {
    if (const std::string v = attribute(hd, "sweeptrace.part", file); v != kFormatVersion)
        throw InputError("'" + file + "': part format " + v + ", this program reads " + kFormatVersion +
                         " (render the part again with this program)");
    if (attribute(hd, "sweeptrace.fractionBits", file) != std::to_string(kSumFractionBits))
        throw InputError("'" + file + "': fixed point with " + attribute(hd, "sweeptrace.fractionBits", file) +
                         " fraction bits, this program uses " + std::to_string(kSumFractionBits));
    PartialImage p;
    const Imath::Box2i win = hd.dataWindow();
    p.id.width = win.max.x - win.min.x + 1;
    p.id.height = win.max.y - win.min.y + 1;
    // A part is a render's film, whose sides are at most kMaxPartSide (scene/film_limits.hpp): a
    // header claiming more is no part this program wrote, refused before anything is allocated.
    if (win.min.x != 0 || win.min.y != 0 || p.id.width < 1 || p.id.height < 1 || p.id.width > kMaxPartSide ||
        p.id.height > kMaxPartSide)
        throw InputError("'" + file + "': data window is not 1.." + std::to_string(kMaxPartSide) +
                         " pixels a side from (0, 0)");
    p.id.scene_hash = attribute(hd, "sweeptrace.sceneHash", file);
    p.id.seed = number<std::uint64_t>(attribute(hd, "sweeptrace.seed", file), "sweeptrace.seed", file);
    p.id.max_depth = static_cast<int>(number(attribute(hd, "sweeptrace.maxDepth", file), "sweeptrace.maxDepth", file));
    p.id.accel = attribute(hd, "sweeptrace.accel", file);
    p.id.integrator = attribute(hd, "sweeptrace.integrator", file);
    p.id.sampler = attribute(hd, "sweeptrace.sampler", file);
    if (p.id.sampler != "sobol" && p.id.sampler != "sobol-halves" && p.id.sampler != "independent")
        throw InputError("'" + file + "': sweeptrace.sampler is '" + p.id.sampler + "', not sobol, sobol-halves or independent");
    p.id.adaptive = attribute(hd, "sweeptrace.adaptive", file);
    if (p.id.adaptive != "off" && p.id.adaptive != "on" && p.id.adaptive != "relative")
        throw InputError("'" + file + "': sweeptrace.adaptive is '" + p.id.adaptive + "', not off, on or relative");
    p.id.aovs = attribute(hd, "sweeptrace.aovs", file);
    if (p.id.aovs != "off" && p.id.aovs != "on")
        throw InputError("'" + file + "': sweeptrace.aovs is '" + p.id.aovs + "', not off or on");
    p.id.version = attribute(hd, "sweeptrace.version", file);
    p.id.spp = static_cast<int>(number(attribute(hd, "sweeptrace.spp", file), "sweeptrace.spp", file));
    const std::string range = attribute(hd, "sweeptrace.samples", file);
    const auto colon = range.find(':');
    if (colon == std::string::npos) throw InputError("'" + file + "': sweeptrace.samples is '" + range + "', not A:B");
    p.sample_begin = static_cast<int>(number(range.substr(0, colon), "sweeptrace.samples", file));
    p.sample_end = static_cast<int>(number(range.substr(colon + 1), "sweeptrace.samples", file));
    if (p.sample_begin < 0 || p.sample_end <= p.sample_begin || p.sample_end > p.id.spp)
        throw InputError("'" + file + "': samples " + range + " is not a range inside [0, " + std::to_string(p.id.spp) + ")");
    return p;
}

}  // namespace

void write_partial(const PartialImage& part, const std::filesystem::path& path) {
    if (part.sums.size() != static_cast<std::size_t>(part.id.width) * static_cast<std::size_t>(part.id.height) ||
        part.sums.empty())
        throw InputError("cannot write '" + path.string() + "': part of " + std::to_string(part.id.width) + "x" +
                         std::to_string(part.id.height) + " holds " + std::to_string(part.sums.size()) + " sums");
    if (part.id.adaptive != "off" && part.counts.size() != part.sums.size())
        throw InputError("cannot write '" + path.string() + "': an adaptive part needs a count per pixel");
    if ((part.id.aovs == "on" ? part.sums.size() : 0) != part.features.size())
        throw InputError("cannot write '" + path.string() + "': a part with feature outputs needs their sums per pixel, and only it");
    const std::vector<std::uint32_t> words = words_of(part.sums);
    const std::vector<std::uint32_t> counts = counts_of(part);
    const std::vector<std::uint32_t> features = feature_words_of(part);
    write_atomically(path, [&](const std::filesystem::path& temp) {
        try {
            write_exr_part(part, words, counts, features, temp);
        } catch (const std::exception& e) {
            throw InputError("cannot write '" + path.string() + "': " + e.what());
        }
    });
}

PartialImage read_partial_header(const std::filesystem::path& path) {
    const std::string file = path.string();
    if (const std::string problem = file_kind_problem(path); !problem.empty())
        throw InputError("cannot read '" + file + "': " + problem);
    try {
        Imf::InputFile in(path.c_str());
        return header_part(in.header(), file);
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError("cannot read '" + file + "': not a valid EXR part (" + e.what() + ")");
    }
}

PartialImage read_partial(const std::filesystem::path& path) {
    const std::string file = path.string();
    if (const std::string problem = file_kind_problem(path); !problem.empty())
        throw InputError("cannot read '" + file + "': " + problem);
    try {
        Imf::InputFile in(path.c_str());
        PartialImage p = header_part(in.header(), file);
        const int w = p.id.width;
        std::vector<std::uint32_t> words(static_cast<std::size_t>(w) * p.id.height * kSumChannels);
        Imf::FrameBuffer frame;
        const std::size_t xs = kSumChannels * sizeof(std::uint32_t);
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < kWords; ++k) {
                if (!in.header().channels().findChannel(sum_channel(c, k)))
                    throw InputError("'" + file + "': not a sweeptrace part (no " + sum_channel(c, k) + " channel)");
                frame.insert(sum_channel(c, k), Imf::Slice(Imf::UINT, reinterpret_cast<char*>(words.data()) +
                                                                          (c * kWords + k) * sizeof(std::uint32_t),
                                                           xs, xs * w));
            }
        std::vector<std::uint32_t> counts;
        if (p.id.adaptive != "off") {
            if (!in.header().channels().findChannel(kCountChannel))
                throw InputError("'" + file + "': an adaptive part without its " + kCountChannel + " channel");
            counts.resize(static_cast<std::size_t>(w) * p.id.height);
            frame.insert(kCountChannel, Imf::Slice(Imf::UINT, reinterpret_cast<char*>(counts.data()), sizeof(std::uint32_t),
                                                   sizeof(std::uint32_t) * w));
        }
        std::vector<std::uint32_t> features;
        if (p.id.aovs == "on") {
            const std::vector<std::string>& names = feature_word_names();
            features.resize(static_cast<std::size_t>(w) * p.id.height * kFeatureWords);
            const std::size_t fs = kFeatureWords * sizeof(std::uint32_t);
            for (int k = 0; k < kFeatureWords; ++k) {
                const std::string& name = names[static_cast<std::size_t>(k)];
                if (!in.header().channels().findChannel(name))
                    throw InputError("'" + file + "': a part with feature outputs without its " + name + " channel");
                frame.insert(name, Imf::Slice(Imf::UINT, reinterpret_cast<char*>(features.data()) + k * sizeof(std::uint32_t), fs, fs * w));
            }
        }
        in.setFrameBuffer(frame);
        in.readPixels(0, p.id.height - 1);
        if (checksum_of(p, words, counts, features) != attribute(in.header(), "sweeptrace.checksum", file))
            throw InputError("'" + file + "': checksum does not match its contents (damaged or edited part)");
        p.sums = sums_of(words);
        for (const std::uint32_t c : counts) {
            if (c > static_cast<std::uint32_t>(std::numeric_limits<int>::max()))
                throw InputError("'" + file + "': a pixel's count " + std::to_string(c) + " does not fit in an int");
            p.counts.push_back(static_cast<int>(c));
        }
        p.features.resize(features.size() / kFeatureWords);
        for (std::size_t i = 0; i < p.features.size(); ++i) {
            p.features[i] = feature_from_words(features.data() + i * kFeatureWords);
            // The halves' counts must be the pixel's: a checksum-valid part is one this program
            // wrote, but a mismatch would make the feature means lie, so it is refused, not trusted.
            const FeatureSums& f = p.features[i];
            if (f.count[0] < 0 || f.count[1] < 0 || std::int64_t{f.count[0]} + f.count[1] != p.count(i))
                throw InputError("'" + file + "': pixel " + std::to_string(i) + "'s feature sample counts do not add up to its count");
        }
        return p;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError("cannot read '" + file + "': not a valid EXR part (" + e.what() + ")");
    }
}

}  // namespace sweeptrace
