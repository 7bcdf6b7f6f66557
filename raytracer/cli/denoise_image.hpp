#pragma once
// Denoising a feature image file into an image file: what `sweeptrace denoise` does, and what
// `render --denoise` does after writing its feature image (which it keeps: the raw render is
// always beside the denoised one).
#include <filesystem>
#include <string>

namespace sweeptrace {

// Throws InputError unless `out` has an image extension the writer knows (.exr, .pfm, .png) and
// its folder exists: checked before any work.
void check_denoise_output(const std::filesystem::path& out);

// Throws InputError naming `what` when NFOR's copy of a width x height image and its working
// buffers (nfor_memory_bytes) would not fit the memory available: render --denoise asks before
// it renders, denoise_file before it filters.
void check_denoise_memory(const std::string& what, int width, int height, int threads);

struct DenoiseReport {
    int width = 0, height = 0;
    double seconds = 0.0;  // wall time of the filter alone
};

// Reads `in` (denoise/feature_channels.hpp names what it needs), checks that its channels and
// NFOR's working memory (nfor_memory_bytes) fit the memory available before allocating them, runs
// NFOR on `threads` threads (0: all cores) and writes the denoised colour to `out` atomically.
// Throws InputError naming the file and what is wrong; then nothing is written.
DenoiseReport denoise_file(const std::filesystem::path& in, const std::filesystem::path& out, int threads);

}  // namespace sweeptrace
