#include "raytracer/cli/render_part.hpp"

#include <charconv>

#include "raytracer/input_error.hpp"

namespace sweeptrace {
namespace {

bool parse_int(const std::string& s, int& v) {
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return !s.empty() && ec == std::errc() && end == s.data() + s.size();
}

}  // namespace

SampleRange parse_sample_range(const std::string& text, int spp) {
    const auto colon = text.find(':');
    SampleRange r;
    if (colon == std::string::npos || !parse_int(text.substr(0, colon), r.begin) ||
        !parse_int(text.substr(colon + 1), r.end))
        throw InputError("--samples '" + text + "': expected A:B, the sample indices [A, B) to render");
    if (r.begin < 0 || r.end <= r.begin || r.end > spp)
        throw InputError("--samples '" + text + "': need 0 <= A < B <= spp (" + std::to_string(spp) +
                         ", the whole render's samples per pixel: --spp or the scene's film.spp)");
    return r;
}

bool is_finished_part(const std::filesystem::path& path, const RenderIdentity& id, SampleRange range) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return false;
    try {
        const PartialImage p = read_partial(path);
        return p.id == id && p.sample_begin == range.begin && p.sample_end == range.end;
    } catch (const InputError&) {
        return false;
    }
}

void write_part(const RenderResult& result, const RenderIdentity& id, int first_sample,
                const std::filesystem::path& path) {
    PartialImage part;
    part.id = id;
    part.sample_begin = first_sample;
    part.sample_end = first_sample + result.stats.completed_spp;
    part.sums = result.sums;
    // Adaptive: each pixel's own count (a range inside the pilot is uniform: completed_spp each).
    if (id.adaptive != "off")
        part.counts = !result.pixel_samples.empty() ? result.pixel_samples
                                                    : std::vector<int>(result.sums.size(), result.stats.completed_spp);
    if (id.aovs == "on") part.features = result.features;
    write_partial(part, path);
}

}  // namespace sweeptrace
