// denoise_file (denoise_image.hpp): read, check, budget, filter, write.
#include "raytracer/cli/denoise_image.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <system_error>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include "raytracer/accel/simd_path.hpp"
#include "raytracer/denoise/feature_channels.hpp"
#include "raytracer/denoise/nfor.hpp"
#include "raytracer/image/exr_channels.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/load_budget.hpp"

namespace sweeptrace {

void check_denoise_output(const std::filesystem::path& out) {
    const std::string ext = lowercase_extension(out);
    if (ext != ".png" && ext != ".pfm" && ext != ".exr")
        throw InputError("output '" + out.string() + "': unknown image extension '" + ext + "' (use .png, .pfm or .exr)");
    const std::filesystem::path dir = out.parent_path();
    std::error_code ec;
    if (!dir.empty() && !std::filesystem::is_directory(dir, ec))
        throw InputError("output '" + out.string() + "': directory '" + dir.string() + "' does not exist");
}

void check_denoise_memory(const std::string& what, int width, int height, int threads) {
    LoadBudgetScope budget;
    const std::size_t features = denoise::feature_channel_names().size();
    const int workers = threads > 0 ? threads : tbb::this_task_arena::max_concurrency();
    charge_load_memory(std::uint64_t(width) * std::uint64_t(height) * 4 * (3 + features) * sizeof(float), what,
                       "NFOR's copy of the colour and features");
    charge_load_memory(denoise::nfor_memory_bytes(width, height, int(features), workers), what, "NFOR's working buffers");
}

namespace {

// The filters' loops in AVX-512 or AVX2 where the CPU has them (the same bits as the baseline's):
// SWEEPTRACE_SIMD=scalar forces the baseline (simd_path.hpp), SWEEPTRACE_SIMD=avx2 stops at AVX2
// (to measure one against the other).
denoise::FilterIsa denoise_isa() {
    if (default_simd_path() != SimdPath::Avx2) return denoise::FilterIsa::Baseline;
    const char* forced = std::getenv("SWEEPTRACE_SIMD");
    if (forced && std::strcmp(forced, "avx2") == 0) return denoise::FilterIsa::Avx2;
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx512f") ? denoise::FilterIsa::Avx512 : denoise::FilterIsa::Avx2;
}

}  // namespace

DenoiseReport denoise_file(const std::filesystem::path& in, const std::filesystem::path& out, int threads) {
    if (lowercase_extension(in) != ".exr")
        throw InputError("cannot denoise '" + in.string() + "': a feature image is an .exr file (render --aovs writes one)");
    denoise::NforInput input;
    {
        LoadBudgetScope budget;  // the channels read, then (joining it) NFOR's copy and buffers
        const ExrChannels channels = read_exr_channels(in);
        check_denoise_memory(in.string(), channels.width, channels.height, threads);
        input = denoise::nfor_input(channels, in.string());
    }
    std::optional<tbb::global_control> allow;  // as the renderer: an explicit --threads above the cores is honoured
    if (threads > tbb::this_task_arena::max_concurrency())
        allow.emplace(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    const auto start = std::chrono::steady_clock::now();
    denoise::Planes result;
    const denoise::FilterIsa isa = denoise_isa();
    arena.execute([&] { result = denoise::nfor(input, isa); });
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    Image image(result.width, result.height);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = {result.channel(0)[i], result.channel(1)[i], result.channel(2)[i]};
    write_image(image, out);
    return {image.width, image.height, seconds};
}

}  // namespace sweeptrace
