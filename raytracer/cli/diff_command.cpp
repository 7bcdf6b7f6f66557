// `sweeptrace diff A B`: metrics, FLIP, the verdict, then an optional heatmap.
// Exit 0 within tolerance, 1 over it, 2 bad input, 4 a warning (within the limits, over a warn level).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "raytracer/cli/commands.hpp"
#include "raytracer/cli/diff_folder.hpp"
#include "raytracer/cli/diff_pair.hpp"
#include "raytracer/cli/output_guard.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace {
namespace {

struct DiffArgs {
    std::string a, b, heatmap, heatmap_of = "flip", variance_a, variance_b;
    std::string tone_mapper = "aces";
    std::vector<float> background{0.0f, 0.0f, 0.0f};
    bool linear = false, flip_details = false;
    double heatmap_scale = 0.0;
    FolderArgs folder;
    DiffSettings settings;
};

int write_heatmap(const DiffArgs& args, const PairReport& r) {
    if (args.heatmap.empty()) return r.exit_code();
    try {
        Image heat;
        if (args.heatmap_of == "flip") {
            heat = flip_heatmap(r.flip);
        } else {
            const Image a = read_image(args.a), b = read_image(args.b);
            const double scale = args.heatmap_scale > 0.0 ? args.heatmap_scale : 2.0 * args.settings.metric_options.pixel_threshold;
            heat = difference_heatmap(a, b, args.settings.metric_options, scale);
        }
        write_image(heat, args.heatmap);
        std::printf("  heatmap              %s (%s; black 0, blue, cyan, green, yellow, red at %s)\n",
                    args.heatmap.c_str(), args.heatmap_of == "flip" ? "FLIP" : "largest channel difference",
                    args.heatmap_of == "flip" ? "1" : "the scale");
    } catch (const InputError& e) {
        // The verdict is already printed; a failing one keeps its exit code 1.
        std::fprintf(stderr, "sweeptrace: error: %s\n", e.what());
        return r.exit_code() == diff_exit_fail ? diff_exit_fail : diff_exit_bad_input;
    }
    return r.exit_code();
}

void prepare_settings(DiffArgs& args, const CLI::App& cmd) {
    DiffSettings& s = args.settings;
    s.metric_options.space = args.linear ? DiffSpace::Linear : DiffSpace::Display;
    s.max_flip_given = cmd.count("--max-flip") > 0;
    s.background = {args.background[0], args.background[1], args.background[2]};
    s.flip.tone_mapper = args.tone_mapper == "reinhard" ? FlipToneMapper::Reinhard : FlipToneMapper::Aces;
}

int run_diff(DiffArgs& args, const CLI::App& cmd) {
    prepare_settings(args, cmd);
    if (!args.folder.golden.empty() || !args.folder.actual.empty()) {
        if (!args.a.empty() || !args.b.empty())
            throw InputError("give either two images A B or --golden DIR --actual DIR, not both");
        return run_diff_folders(args.folder, args.settings);
    }
    if (args.a.empty() || args.b.empty()) throw InputError("diff needs two images A B (or --golden DIR --actual DIR)");
    check_outputs({{"--heatmap", args.heatmap}}, {{"image A", args.a},
                                                  {"image B", args.b},
                                                  {"--variance-a image", args.variance_a},
                                                  {"--variance-b image", args.variance_b}});
    const PairReport r = compare_pair({args.a, args.b, args.variance_a, args.variance_b}, args.settings);
    print_report(r, stdout);
    return write_heatmap(args, r);
}

void add_threshold_options(CLI::App* cmd, DiffArgs& a) {
    DiffSettings& s = a.settings;
    cmd->add_option("--max-flip", s.max_flip, "Largest accepted mean FLIP (with variances: applied only when given)")
        ->capture_default_str()->check(CLI::Range(0.0, 1.0));
    cmd->add_option("--warn-flip", s.warn_flip, "Mean FLIP above this, within the limits, is a warning (exit 4)")
        ->capture_default_str()->check(CLI::Range(0.0, 1.0));
    cmd->add_option("--max-local-flip", s.max_local_flip, "Largest accepted mean FLIP over the worst 3x3 pixels")
        ->capture_default_str()->check(CLI::Range(0.0, 1.0));
    cmd->add_option("--max-abs", s.max_abs, "Hard limit on any pixel's channel difference (default: off)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--max-rmse", s.max_rmse, "Largest accepted RMSE (not applied with variances)")
        ->capture_default_str()->check(CLI::NonNegativeNumber);
    cmd->add_option("--max-share", s.max_share, "Largest accepted share (0..1) of pixels over the pixel threshold")
        ->capture_default_str()->check(CLI::Range(0.0, 1.0));
    cmd->add_option("--pixel-threshold", s.metric_options.pixel_threshold, "A pixel differs when a channel differs by more")
        ->capture_default_str()->check(CLI::NonNegativeNumber);
    cmd->add_option("--max-delta-e", s.max_delta_e, "Largest accepted mean delta E of the blurred CIELAB metric (default: off)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--max-alpha", s.max_alpha, "Largest accepted alpha difference")->capture_default_str()
        ->check(CLI::Range(0.0, 1.0));
}

void add_flip_options(CLI::App* cmd, DiffArgs& a) {
    FlipOptions& f = a.settings.flip;
    cmd->add_flag("--flip", a.flip_details,
                  "Accepted for clarity: FLIP (mean, weighted median and quartiles, max, worst 3x3) is always computed, "
                  "printed and judged");
    cmd->add_option("--ppd", f.pixels_per_degree, "FLIP pixels per degree of visual angle")->capture_default_str()
        ->check(CLI::PositiveNumber);
    cmd->add_option("--flip-mode", a.settings.flip_mode, "auto (HDR-FLIP when both are .exr/.pfm), ldr or hdr")
        ->capture_default_str()->check(CLI::IsMember({"auto", "ldr", "hdr"}));
    cmd->add_option("--tone-mapper", a.tone_mapper, "HDR-FLIP tone mapper")->capture_default_str()
        ->check(CLI::IsMember({"aces", "reinhard"}));
    cmd->add_option("--start-exposure", f.start_exposure, "HDR-FLIP first exposure in stops (default: from B)");
    cmd->add_option("--stop-exposure", f.stop_exposure, "HDR-FLIP last exposure in stops (default: from B)");
    cmd->add_option("--exposures", f.exposures, "HDR-FLIP number of exposures (default: max(2, ceil(stop - start)))")
        ->check(CLI::PositiveNumber);
}

}  // namespace

void add_diff_command(CLI::App& app, int& exit_code) {
    auto args = std::make_shared<DiffArgs>();
    auto* cmd = app.add_subcommand(
        "diff",
        "Compare image A against the reference B (.png, .pfm, .exr), or every image of --actual DIR against\n"
        "the golden of the same name in --golden DIR. Exit 0 within tolerance, 1 over it, 2 bad input,\n"
        "4 a warning (within the limits, mean FLIP over --warn-flip).\nDefault verdict: mean FLIP (LDR, or HDR-FLIP for two float files) <= 0.04 and\n"
        "the worst 3x3 pixels' mean FLIP <= 0.3, RMSE <= 0.05 and <= 1% of pixels over the pixel threshold\n"
        "(display space: clamped, sRGB-encoded, unless --linear). These reject a 12x12 hole, a 4x4 white\n"
        "square, +-10% exposure, a 15% tint and a 1-px blur, and accept 8-bit rounding. Monte Carlo renders at\n"
        "different seeds: give --variance-a and --variance-b (float files from `render --variance`); the\n"
        "z-test on block means then replaces the RMSE, share and FLIP limits. Alpha, when present, is\n"
        "compared (--max-alpha) and both images are composited over --background (linear, default black).");
    cmd->add_option("A", args->a, "Image under test");
    cmd->add_option("B", args->b, "Reference image");
    cmd->add_option("--heatmap", args->heatmap, "Write a false-colour image of the differences (after the verdict)");
    cmd->add_option("--heatmap-of", args->heatmap_of, "flip (the FLIP map) or abs (largest channel difference)")
        ->capture_default_str()->check(CLI::IsMember({"flip", "abs"}));
    cmd->add_option("--heatmap-scale", args->heatmap_scale, "abs heatmap: difference shown as full red (default: 2 x pixel threshold)")
        ->check(CLI::PositiveNumber);
    cmd->add_flag("--linear", args->linear, "Per-channel metrics on linear values, unclamped (HDR .pfm/.exr)");
    cmd->add_option("--background", args->background, "Linear RGB under images with alpha")->expected(3)
        ->capture_default_str();
    cmd->add_option("--variance-a", args->variance_a, "Per-pixel variance of A's pixel means (.exr/.pfm)");
    cmd->add_option("--variance-b", args->variance_b, "Per-pixel variance of B's pixel means (.exr/.pfm)");
    cmd->add_option("--false-alarm", args->settings.false_alarm,
                    "Noise test: family-wise false-alarm rate over all blocks and channels (Bonferroni)")
        ->capture_default_str()->check(CLI::Range(1e-12, 0.5));
    cmd->add_option("--block", args->settings.block, "Noise test block size in pixels")->capture_default_str()
        ->check(CLI::Range(1, 256));
    add_threshold_options(cmd, *args);
    add_flip_options(cmd, *args);
    add_folder_options(cmd, args->folder);
    cmd->callback([args, cmd, &exit_code] { exit_code = run_diff(*args, *cmd); });
}

}  // namespace sweeptrace
