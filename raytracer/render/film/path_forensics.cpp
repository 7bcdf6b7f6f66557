#include "raytracer/render/film/path_forensics.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <tuple>

#include "raytracer/image/srgb.hpp"
#include "raytracer/render/lights/lights.hpp"
#include "raytracer/render/render_tiles.hpp"
#include "raytracer/render/sampling/sampling.hpp"

namespace sweeptrace {

namespace {

// Colours (sRGB) of the path types in the picture (see palette_order); every further type is grey. Chosen to stay apart for the common colour blindnesses
// (Okabe and Ito's palette).
constexpr std::array<std::array<float, 3>, 8> kPalette{{
    {0.90f, 0.62f, 0.00f},  // orange
    {0.34f, 0.71f, 0.91f},  // sky blue
    {0.00f, 0.62f, 0.45f},  // bluish green
    {0.94f, 0.89f, 0.26f},  // yellow
    {0.00f, 0.45f, 0.70f},  // blue
    {0.84f, 0.37f, 0.00f},  // vermilion
    {0.80f, 0.47f, 0.65f},  // reddish purple
    {0.55f, 0.35f, 0.20f},  // brown
}};
constexpr std::array<float, 3> kOther{0.6f, 0.6f, 0.6f};

std::string json_string(const std::string& s) {
    std::string out = "\"";
    for (const char ch : s) {
        const auto c = static_cast<unsigned char>(ch);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += ch;
        } else if (c < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            out += buf;
        } else {
            out += ch;
        }
    }
    return out + "\"";
}

void add_to(PathMoments& t, const PathMoments& m) {
    t.variance += m.variance;
    t.second += m.second;
    t.first += m.first;
}

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

}  // namespace

PathTally::Kind PathTally::kind_of(const MaterialParameters& m, bool delta_lobe) {
    if (delta_lobe) return Specular;
    return m.type == Material::Type::Diffuse ? Diffuse : Glossy;
}

void PathTally::scatter(Kind kind, std::uint32_t material, float factor) {
    push(key_, kind);
    note_factor(material, factor);
}

void PathTally::add(const glm::vec3& c, std::int32_t light) { add_with(key_, largest_material_, c, light); }

void PathTally::add_light_sample(Kind kind, std::uint32_t material, float factor, const glm::vec3& c, std::int32_t light) {
    PathKey k = key_;
    push(k, kind);
    const std::int32_t m = factor > largest_ ? static_cast<std::int32_t>(material) : largest_material_;
    add_with(k, m, c, light);
}

void PathTally::add_with(const PathKey& k, std::int32_t material, const glm::vec3& c, std::int32_t light) {
    const float v = luminance(c);
    if (!(v != 0.0f)) return;
    PathKey key = k;
    key.material = material;
    key.light = light;
    found_.push_back({key, v});
}

void PathForensics::start(int width, int height, int tile_size, const LightSet& lights) {
    light_names_.clear();
    for (std::int32_t i = 0; i < lights.light_count(); ++i) light_names_.push_back(lights.light_name(i));
    width_ = width;
    height_ = height;
    regions_.clear();
    pixel_sum_.assign(static_cast<std::size_t>(width) * height, 0.0);
    pixel_pass_.assign(pixel_sum_.size(), 0.0);
    passes_ = 0;
    most_keys_ = 0;
    for (int y0 = 0; y0 < height; y0 += tile_size)
        for (int x0 = 0; x0 < width; x0 += tile_size) {
            Region r;
            r.x0 = x0;
            r.y0 = y0;
            r.x1 = std::min(x0 + tile_size, width);
            r.y1 = std::min(y0 + tile_size, height);
            regions_.push_back(std::move(r));
        }
}

void PathForensics::finish_sample(int tile, std::size_t pixel, const PathTally& tally, const glm::vec3& sample) {
    Region& r = regions_[static_cast<std::size_t>(tile)];
    ++r.pending_samples;
    const double x = luminance(sample);
    pixel_pass_[pixel] = x;
    double raw = 0.0;
    for (const PathTally::Found& f : tally.found()) raw += f.value;
    if (raw == 0.0 || x == 0.0) return;
    // The pixel's mean over the passes before this one: independent of this sample.
    const double m = passes_ > 0 ? pixel_sum_[pixel] / passes_ : 0.0;
    // The filter weight, a film clamp or a non-finite sample made black: scale every part alike.
    const double scale = x / raw;
    for (const PathTally::Found& f : tally.found()) {
        const double c = scale * f.value;
        auto it = r.pending.find(f.key);
        if (it == r.pending.end())
            it = r.pending.try_emplace(r.pending.size() < kRegionTypes ? f.key : PathKey::other()).first;
        add_to(it->second, PathMoments{passes_ > 0 ? c * (x - m) : 0.0, c * x, c});
    }
}

// The pass's sums into the totals, within kRegionTypes keys (the header comment says how).
void PathForensics::merge_pass(Region& r) {
    std::vector<std::pair<PathKey, PathMoments>> fresh;  // keys the totals do not have yet
    for (const auto& [key, m] : r.pending) {
        const auto it = r.totals.find(key);
        if (it != r.totals.end()) add_to(it->second, m);
        else fresh.emplace_back(key, m);
    }
    // Largest second moment first (ties: the smaller key), into the room left, then each in the
    // place of the kept key with the smallest second moment while it is larger.
    const auto larger = [](const auto& a, const auto& b) {
        return a.second.second != b.second.second ? a.second.second > b.second.second : a.first < b.first;
    };
    std::sort(fresh.begin(), fresh.end(), larger);
    const auto kept = [&r] { return r.totals.size() - r.totals.count(PathKey::other()); };
    std::size_t next = 0;
    for (; next < fresh.size() && kept() < kRegionTypes; ++next) r.totals.insert(fresh[next]);
    if (next < fresh.size()) {
        std::vector<std::pair<PathKey, PathMoments>> smallest;
        for (const auto& entry : r.totals)
            if (!entry.first.is_other()) smallest.push_back(entry);
        std::sort(smallest.begin(), smallest.end(), [&](const auto& a, const auto& b) { return larger(b, a); });
        PathMoments& other = r.totals[PathKey::other()];
        std::size_t k = 0;
        for (; next < fresh.size(); ++next) {
            if (k < smallest.size() && fresh[next].second.second > smallest[k].second.second) {
                add_to(other, smallest[k].second);
                r.totals.erase(smallest[k].first);
                r.totals.insert(fresh[next]);
                ++k;
            } else {
                add_to(other, fresh[next].second);
            }
        }
    }
    r.pending.clear();
}

std::size_t PathForensics::most_region_keys() const { return most_keys_; }

std::uint64_t PathForensics::memory_bytes(int width, int height) {
    // A std::map node: the key and sums, three links and the colour, the allocator's header.
    constexpr std::uint64_t node = sizeof(std::pair<const PathKey, PathMoments>) + 4 * sizeof(void*) + 16;
    // The report's per key: a node of the image-wide map, and a Row with its three names (a path
    // of 30 vertices is 66 characters, past a string's inline buffer).
    constexpr std::uint64_t report = node + sizeof(Row) + 3 * 80;
    const std::uint64_t per_region = sizeof(Region) + (kRegionTypes + 1) * (2 * node + report);
    return render_tile_count(width, height) * per_region + std::uint64_t(width) * std::uint64_t(height) * 2 * sizeof(double);
}

void PathForensics::end_pass() {
    for (Region& r : regions_) {
        merge_pass(r);
        most_keys_ = std::max(most_keys_, r.totals.size());
        r.samples += r.pending_samples;
        if (passes_ > 0) r.variance_samples += r.pending_samples;
        r.pending_samples = 0;
    }
    for (std::size_t i = 0; i < pixel_sum_.size(); ++i) pixel_sum_[i] += pixel_pass_[i];
    ++passes_;
}

void PathForensics::drop_pass() {
    for (Region& r : regions_) {
        r.pending.clear();
        r.pending_samples = 0;
    }
}

std::string PathForensics::path_text(const PathKey& k) const {
    if (k.is_other()) return "other types";
    std::string s = "L";
    if (k.length >= PathKey::kMaxVertices) s += " ...";
    for (int i = std::min<int>(k.length, PathKey::kMaxVertices) - 1; i >= 0; --i) {
        const auto kind = (k.vertices >> (2 * i)) & 3u;
        s += kind == PathTally::Medium  ? " V"
             : kind == PathTally::Diffuse ? " D"
             : kind == PathTally::Glossy  ? " G"
                                          : " S";
    }
    return s + " E";
}

std::string PathForensics::light_text(std::int32_t light) const {
    if (light == -1) return "-";  // no one light: a region's "other types" (PathKey::other)
    if (light == PathKey::kBackground) return "background";
    if (light == PathKey::kMediumEmission) return "medium emission";
    return light >= 0 && static_cast<std::size_t>(light) < light_names_.size() ? light_names_[static_cast<std::size_t>(light)] : "?";
}

std::string PathForensics::material_text(std::int32_t material) const {
    if (material < 0) return "-";
    const std::string& name = scene_.materials[static_cast<std::size_t>(material)].name;
    return name.empty() ? "material " + std::to_string(material) : name;
}

std::map<PathKey, PathMoments> PathForensics::image_totals(bool by_path) const {
    std::map<PathKey, PathMoments> all;
    for (const Region& r : regions_)
        for (const auto& [key, m] : r.totals) add_to(all[by_path ? path_only(key) : key], m);
    return all;
}

PathForensics::Totals PathForensics::totals() const {
    Totals t;
    for (const Region& r : regions_) {
        t.samples += r.samples;
        for (const auto& [key, m] : r.totals) {
            t.variance += m.variance;
            t.second += m.second;
            t.first += m.first;
        }
    }
    return t;
}

std::vector<PathForensics::Row> PathForensics::rows(bool by_path, std::size_t limit) const {
    const std::map<PathKey, PathMoments> all = image_totals(by_path);
    double variance = 0.0, second = 0.0, first = 0.0;
    for (const auto& [key, m] : all) {
        variance += m.variance;
        second += m.second;
        first += m.first;
    }
    std::vector<Row> out;
    for (const auto& [key, m] : all) {
        Row row;
        row.path = path_text(key);
        row.light = by_path ? "" : light_text(key.light);
        row.material = by_path ? "" : material_text(key.material);
        row.variance = variance > 0.0 ? m.variance / variance : 0.0;
        row.second = second > 0.0 ? m.second / second : 0.0;
        row.first = first > 0.0 ? m.first / first : 0.0;
        out.push_back(std::move(row));
    }
    // Ties broken by the text, so the order never depends on anything but the sums.
    std::stable_sort(out.begin(), out.end(), [](const Row& a, const Row& b) {
        if (a.variance != b.variance) return a.variance > b.variance;
        return std::tie(a.path, a.light, a.material) < std::tie(b.path, b.light, b.material);
    });
    if (out.size() > limit) out.resize(limit);
    return out;
}

std::string PathForensics::table(std::size_t limit) const {
    std::ostringstream s;
    char buf[512];
    s << "noise forensics: share of the pixels' variance, of the second moment E[X^2] and of the mean, by path type\n";
    std::snprintf(buf, sizeof buf, "  %-26s %8s %8s %8s\n", "path (light->eye)", "variance", "E[X^2]", "mean");
    s << buf;
    for (const Row& r : rows(true, limit)) {
        std::snprintf(buf, sizeof buf, "  %-26s %7.1f%% %7.1f%% %7.1f%%\n", r.path.c_str(), 100.0 * r.variance,
                      100.0 * r.second, 100.0 * r.first);
        s << buf;
    }
    s << "by path type, light, and the material of the vertex with the largest throughput factor\n";
    std::snprintf(buf, sizeof buf, "  %-26s %-28s %-20s %8s %8s %8s\n", "path", "light", "largest vertex", "variance",
                  "E[X^2]", "mean");
    s << buf;
    for (const Row& r : rows(false, limit)) {
        std::snprintf(buf, sizeof buf, "  %-26s %-28.28s %-20.20s %7.1f%% %7.1f%% %7.1f%%\n", r.path.c_str(),
                      r.light.c_str(), r.material.c_str(), 100.0 * r.variance, 100.0 * r.second, 100.0 * r.first);
        s << buf;
    }
    return s.str();
}

// The path types that dominate the most regions get the colours (ties: the larger share of the
// image's variance first), so that the picture shows as few grey "other" regions as it can.
std::vector<std::string> PathForensics::palette_order() const {
    std::vector<Row> all = rows(true, std::numeric_limits<std::size_t>::max());
    std::map<std::string, int> regions;
    for (const Region& r : regions_) ++regions[dominant(r)];
    std::stable_sort(all.begin(), all.end(), [&](const Row& a, const Row& b) { return regions[a.path] > regions[b.path]; });
    std::vector<std::string> order;
    for (const Row& r : all) {
        if (order.size() == kPalette.size() || regions[r.path] == 0) break;
        order.push_back(r.path);
    }
    return order;
}

std::string PathForensics::dominant(const Region& r) const {
    std::map<PathKey, double> by_path;
    for (const auto& [key, m] : r.totals) by_path[path_only(key)] += m.variance;
    const PathKey* best = nullptr;
    double best_value = 0.0;
    for (const auto& [key, v] : by_path)
        if (v > best_value) {  // strict: the first (smallest key) wins a tie
            best_value = v;
            best = &key;
        }
    return best == nullptr ? std::string() : path_text(*best);
}

std::string PathForensics::json(int spp) const {
    const std::vector<std::string> order = palette_order();
    auto colour_of = [&](const std::string& path) {
        const auto it = std::find(order.begin(), order.end(), path);
        const std::array<float, 3>& c = it == order.end() ? kOther : kPalette[static_cast<std::size_t>(it - order.begin())];
        char buf[64];  // snprintf, not string concatenation: GCC 12 warns falsely (-Wrestrict) on that
        std::snprintf(buf, sizeof buf, "[%.3g, %.3g, %.3g]", c[0], c[1], c[2]);
        return std::string(buf);
    };
    std::ostringstream s;
    s << "{\n  \"width\": " << width_ << ", \"height\": " << height_ << ", \"spp\": " << spp << ",\n";
    s << "  \"attribution\": \"each contribution c_k of a sample X = sum c_k (luminance) is credited c_k (X - m), m the "
         "pixel's mean over the earlier passes (their sums are Cov(c_k, X), which add up to Var X: variance_share), and "
         "c_k X (sums add up to E[X^2]: second_moment_share)\",\n";
    s << "  \"path_types\": [";
    bool first = true;
    for (const Row& r : rows(true, 1000)) {
        s << (first ? "\n" : ",\n") << "    {\"path\": " << json_string(r.path) << ", \"variance_share\": "
          << number(r.variance) << ", \"second_moment_share\": " << number(r.second) << ", \"mean_share\": " << number(r.first) << ", \"colour\": " << colour_of(r.path)
          << "}";
        first = false;
    }
    s << "\n  ],\n  \"sources\": [";
    first = true;
    for (const Row& r : rows(false, 50)) {
        s << (first ? "\n" : ",\n") << "    {\"path\": " << json_string(r.path) << ", \"light\": " << json_string(r.light)
          << ", \"largest_vertex_material\": " << json_string(r.material) << ", \"variance_share\": "
          << number(r.variance) << ", \"second_moment_share\": " << number(r.second) << ", \"mean_share\": " << number(r.first) << "}";
        first = false;
    }
    s << "\n  ],\n  \"regions\": [";
    first = true;
    for (const Region& r : regions_) {
        double variance = 0.0, second = 0.0, mean = 0.0;
        for (const auto& [key, m] : r.totals) {
            variance += m.variance;
            second += m.second;
            mean += m.first;
        }
        const double n = r.samples > 0 ? double(r.samples) : 1.0;
        const double nv = r.variance_samples > 0 ? double(r.variance_samples) : 1.0;
        s << (first ? "\n" : ",\n") << "    {\"x\": " << r.x0 << ", \"y\": " << r.y0 << ", \"width\": " << r.x1 - r.x0
          << ", \"height\": " << r.y1 - r.y0 << ", \"samples\": " << r.samples << ", \"mean\": " << number(mean / n)
          << ", \"variance\": " << number(variance / nv) << ", \"second_moment\": " << number(second / n) << ", \"dominant\": " << json_string(dominant(r))
          << ", \"top\": [";
        first = false;
        std::vector<std::pair<PathKey, PathMoments>> top(r.totals.begin(), r.totals.end());
        std::stable_sort(top.begin(), top.end(),
                         [](const auto& a, const auto& b) { return a.second.variance > b.second.variance; });
        if (top.size() > 5) top.resize(5);
        bool first_top = true;
        for (const auto& [key, m] : top) {
            s << (first_top ? "" : ", ") << "{\"path\": " << json_string(path_text(key))
              << ", \"light\": " << json_string(light_text(key.light))
              << ", \"largest_vertex_material\": " << json_string(material_text(key.material))
              << ", \"variance_share\": " << number(variance > 0.0 ? m.variance / variance : 0.0) << "}";
            first_top = false;
        }
        s << "]}";
    }
    s << "\n  ]\n}\n";
    return s.str();
}

Image PathForensics::picture(const Image& image) const {
    const std::vector<std::string> order = palette_order();
    Image out(width_, height_);
    // The scene's grey, tone mapped by the image's own mean so that any exposure shows through.
    double mean = 0.0;
    for (const glm::vec3& p : image.pixels) mean += luminance(p);
    mean = image.pixels.empty() ? 1.0 : mean / double(image.pixels.size());
    const float k = mean > 0.0 ? static_cast<float>(0.5 / mean) : 0.0f;
    for (const Region& r : regions_) {
        const std::string d = dominant(r);
        const auto it = std::find(order.begin(), order.end(), d);
        const std::array<float, 3>& c = it == order.end() ? kOther : kPalette[static_cast<std::size_t>(it - order.begin())];
        const bool empty = d.empty();
        for (int y = r.y0; y < r.y1; ++y)
            for (int x = r.x0; x < r.x1; ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * width_ + x;
                const float l = k * luminance(image.pixels[i]);
                const float grey = l / (1.0f + l);  // Reinhard, in display terms
                const bool edge = x == r.x0 || y == r.y0;
                glm::vec3 v;
                for (int ch = 0; ch < 3; ++ch) {
                    const float display = empty ? grey : edge ? 0.5f * c[static_cast<std::size_t>(ch)]
                                                              : 0.55f * c[static_cast<std::size_t>(ch)] + 0.45f * grey;
                    v[ch] = srgb_decode(display);
                }
                out.pixels[i] = v;
            }
    }
    return out;
}

}  // namespace sweeptrace
