// Checking and summing farm parts (partial_image.hpp). The sums are integers, so the order they
// are added in cannot change the result; they are still added in order of their ranges, one
// fixed order, so that the code states no more than it needs.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>

#include "raytracer/image/partial_image.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace {
namespace {

std::string range_text(int begin, int end) { return "[" + std::to_string(begin) + ", " + std::to_string(end) + ")"; }

template <class T>
std::string differs(const char* field, const T& a, const T& b) {
    if (a == b) return {};
    if constexpr (std::is_same_v<T, std::string>) return std::string(field) + " '" + a + "' vs '" + b + "'";
    else return std::string(field) + " " + std::to_string(a) + " vs " + std::to_string(b);
}

// Sorted by range; throws on a different render, an overlap or a gap.
void check_cover(const std::vector<PartialImage>& parts, const std::vector<std::string>& names,
                 const std::vector<std::size_t>& order) {
    const RenderIdentity& id = parts[order[0]].id;
    int covered = 0;  // samples [0, covered) are accounted for
    std::size_t previous = order[0];
    for (std::size_t i : order) {
        const PartialImage& p = parts[i];
        if (p.sample_begin < covered)
            throw InputError("parts '" + names[previous] + "' " +
                             range_text(parts[previous].sample_begin, parts[previous].sample_end) + " and '" + names[i] +
                             "' " + range_text(p.sample_begin, p.sample_end) + " overlap on samples " +
                             range_text(p.sample_begin, std::min(covered, p.sample_end)));
        if (p.sample_begin > covered)
            throw InputError("samples " + range_text(covered, p.sample_begin) + " of the " + std::to_string(id.spp) +
                             "-sample render are missing: no part covers them");
        covered = p.sample_end;
        previous = i;
    }
    if (covered < id.spp)
        throw InputError("samples " + range_text(covered, id.spp) + " of the " + std::to_string(id.spp) +
                         "-sample render are missing: no part covers them");
}

}  // namespace

std::string identity_difference(const RenderIdentity& a, const RenderIdentity& b) {
    for (const std::string& d :
         {differs("scene hash", a.scene_hash, b.scene_hash), differs("width", a.width, b.width),
          differs("height", a.height, b.height), differs("seed", a.seed, b.seed),
          differs("max depth", a.max_depth, b.max_depth), differs("accel", a.accel, b.accel),
          differs("integrator", a.integrator, b.integrator),
          differs("adaptive sampling", a.adaptive, b.adaptive), differs("feature outputs (--aovs)", a.aovs, b.aovs),
          // after --aovs, which changes the scene's sobol to sobol-halves: the cause named first
          differs("sampler", a.sampler, b.sampler),
          differs("program version", a.version, b.version), differs("spp", a.spp, b.spp)})
        if (!d.empty()) return d;
    return {};
}

Image PartialImage::mean() const {
    Image img(id.width, id.height);
    for (std::size_t i = 0; i < sums.size() && i < img.pixels.size(); ++i)
        if (count(i) > 0) img.pixels[i] = mean_of(sums[i], count(i));
    return img;
}

std::vector<std::size_t> check_partials(const std::vector<PartialImage>& parts, const std::vector<std::string>& names) {
    if (parts.empty()) throw InputError("merge: no parts given");
    for (std::size_t i = 1; i < parts.size(); ++i)
        if (const std::string d = identity_difference(parts[0].id, parts[i].id); !d.empty())
            throw InputError("'" + names[i] + "' is not a part of the same render as '" + names[0] + "': " + d);
    std::vector<std::size_t> order(parts.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return parts[a].sample_begin < parts[b].sample_begin; });
    check_cover(parts, names, order);
    return order;
}

void add_part(PartialImage& whole, const PartialImage& part, const std::string& name) {
    if (whole.sums.empty()) whole.sums.assign(part.sums.size(), PixelSum{});
    for (std::size_t px = 0; px < whole.sums.size(); ++px) whole.sums[px] += part.sums[px];
    if (whole.id.aovs == "on") {
        if (whole.features.empty()) whole.features.assign(part.features.size(), FeatureSums{});
        for (std::size_t px = 0; px < whole.features.size() && px < part.features.size(); ++px)
            whole.features[px] += part.features[px];
    }
    if (whole.id.adaptive == "off") return;
    if (whole.counts.empty()) whole.counts.assign(whole.sums.size(), 0);
    for (std::size_t px = 0; px < whole.counts.size(); ++px) {
        const std::int64_t n = std::int64_t{whole.counts[px]} + part.count(px);
        if (n > std::numeric_limits<int>::max())
            throw InputError("'" + name + "': pixel " + std::to_string(px) + "'s samples over all parts do not fit in an int");
        whole.counts[px] = static_cast<int>(n);
    }
}

PartialImage merge_partials(const std::vector<PartialImage>& parts, const std::vector<std::string>& names) {
    const std::vector<std::size_t> order = check_partials(parts, names);
    PartialImage whole;
    whole.id = parts[0].id;
    whole.sample_begin = 0;
    whole.sample_end = whole.id.spp;
    whole.sums.assign(parts[0].sums.size(), PixelSum{});
    for (std::size_t i : order) add_part(whole, parts[i], names[i]);
    return whole;
}

}  // namespace sweeptrace
