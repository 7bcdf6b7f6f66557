#pragma once
// `render --samples A:B -o part.exr`: one farm part (image/partial_image.hpp) instead of an image.
#include <filesystem>
#include <string>

#include "raytracer/image/partial_image.hpp"
#include "raytracer/render/renderer.hpp"

namespace sweeptrace {

struct SampleRange {
    int begin = 0, end = 0;  // [begin, end)
};

// "A:B" with 0 <= A < B <= spp; throws InputError naming --samples and saying why. Under
// adaptive sampling A:B are nominal spp (render/adaptive_sampling.hpp): any split works.
SampleRange parse_sample_range(const std::string& text, int spp);

// True when `path` exists, reads, verifies, and is the part of `id` for exactly `range`: the
// work a re-run task may skip. Anything else (missing, damaged, another render) is false.
bool is_finished_part(const std::filesystem::path& path, const RenderIdentity& id, SampleRange range);

// The part of the samples `result` completed, from `first_sample` on (fewer than asked when the
// render was interrupted: then the part says so, and the merge reports the rest as missing).
// Under adaptive sampling (id.adaptive) the range is nominal spp and each pixel's count is kept.
void write_part(const RenderResult& result, const RenderIdentity& id, int first_sample,
                const std::filesystem::path& path);

}  // namespace sweeptrace
