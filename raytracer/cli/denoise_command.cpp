// `sweeptrace denoise IN.exr -o OUT [--threads N]`: NFOR (denoise/nfor.hpp) on a feature image
// as `render --aovs` writes it (the channels: denoise/feature_channels.hpp). OUT is .exr, .pfm or
// .png (the denoised colour only), written atomically after everything succeeded; it may not be
// the input, which is never modified. Bad input (no such file, a channel missing, layers of
// different sizes, a NaN feature, more memory than is available) exits 2 with one line, and
// nothing is written.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include <tbb/task_arena.h>

#include "raytracer/cli/commands.hpp"
#include "raytracer/cli/denoise_image.hpp"
#include "raytracer/cli/output_guard.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace {

namespace {

struct DenoiseArgs {
    std::string input;
    std::string output;
    int threads = 0;
    bool quiet = false;
};

int run_denoise(const DenoiseArgs& a) {
    const std::filesystem::path in(a.input), out(a.output);
    check_denoise_output(out);
    check_outputs({{"output", out}}, {{"image to denoise", in}});
    const DenoiseReport report = denoise_file(in, out, a.threads);
    if (!a.quiet)
        std::fprintf(stderr, "%s -> %s (%dx%d, NFOR, %.2f s)\n", in.string().c_str(), out.string().c_str(), report.width, report.height,
                     report.seconds);
    return 0;
}

}  // namespace

void add_denoise_command(CLI::App& app, int& exit_code) {
    auto args = std::make_shared<DenoiseArgs>();
    auto* cmd = app.add_subcommand("denoise", "Denoise a feature image of render --aovs by NFOR (docs/denoising.md)");
    cmd->add_option("image", args->input, "Feature image (.exr) as render --aovs writes it")->required();
    cmd->add_option("-o,--output", args->output, "Denoised image (.exr, .pfm or .png); never the input")->required();
    cmd->add_option("--threads", args->threads, "Worker threads, 0 = all cores, at most 1024")
        ->check(CLI::Range(0, 1024))
        ->capture_default_str();
    cmd->add_flag("--quiet", args->quiet, "No summary line");
    cmd->callback([args, &exit_code] { exit_code = run_denoise(*args); });
}

}  // namespace sweeptrace
