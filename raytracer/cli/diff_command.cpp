// `sweeptrace diff A B`: metrics, an optional heatmap, exit 0 within tolerance, 1 over, 2 bad input.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "raytracer/cli/commands.hpp"
#include "raytracer/cli/output_guard.hpp"
#include "raytracer/image/diff.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace {
namespace {

struct DiffArgs {
    std::string a, b, heatmap, noise;
    double max_rmse = 0.05;
    double max_share = 0.01;
    double pixel_threshold = 0.1;
    double max_delta_e = -1.0;  // negative = not checked
    double heatmap_scale = 0.0; // 0 = twice the pixel threshold
    bool linear = false;
};

int run_diff(const DiffArgs& args) {
    if (!args.heatmap.empty()) {
        std::vector<NamedInput> inputs{{"image A", args.a}, {"image B", args.b}};
        if (!args.noise.empty()) inputs.push_back({"--noise image", args.noise});
        refuse_output_over_input(args.heatmap, inputs);
    }
    const Image a = read_image(args.a);
    const Image b = read_image(args.b);
    DiffOptions options;
    options.space = args.linear ? DiffSpace::Linear : DiffSpace::Display;
    options.pixel_threshold = args.pixel_threshold;
    const DiffMetrics m = compare_images(a, b, options);

    std::printf("%s vs %s: %dx%d, %s space\n", args.a.c_str(), args.b.c_str(), m.width, m.height,
                args.linear ? "linear" : "display (sRGB, clamped)");
    std::printf("  RMSE                 %.6f\n", m.rmse);
    std::printf("  PSNR                 %.2f dB\n", m.psnr);
    std::printf("  mean |a-b|           %.6f\n", m.mean_abs);
    std::printf("  max |a-b|            %.6f at (%d, %d)\n", m.max_abs, m.max_x, m.max_y);
    std::printf("  pixels over %-8.4g %.4f %%\n", args.pixel_threshold, 100.0 * m.share_over);
    std::printf("  mean delta E (blurred CIELAB, simplified, not FLIP)  %.4f; pixels over 2.3: %.4f %%\n",
                m.mean_delta_e, 100.0 * m.share_delta_e_over_jnd);
    if (m.non_finite_a + m.non_finite_b > 0)
        std::printf("  non-finite pixels    %zu in A, %zu in B\n", m.non_finite_a, m.non_finite_b);

    std::vector<std::string> over;
    auto check = [&over](double value, double limit, const char* what) {
        if (value > limit) {
            char text[160];
            std::snprintf(text, sizeof text, "%s %.6g > %.6g", what, value, limit);
            over.push_back(text);
        }
    };
    check(m.rmse, args.max_rmse, "RMSE");
    check(m.share_over, args.max_share, "share of pixels over the pixel threshold");
    if (args.max_delta_e >= 0.0) check(m.mean_delta_e, args.max_delta_e, "mean delta E");
    if (m.non_finite_a + m.non_finite_b > 0) over.push_back("non-finite pixels");

    if (!args.noise.empty()) {
        const Image second = read_image(args.noise);
        const MeanAndVariance halves = combine_halves(a, second);
        BlockTestOptions block_options;
        block_options.golden_is_8bit = std::filesystem::path(args.b).extension() == ".png";
        const BlockTestResult r = block_test(b, halves.mean, halves.variance, block_options);
        std::printf("  %s\n", r.summary().c_str());
        if (!r.pass()) over.push_back("block test");
    }

    if (!args.heatmap.empty()) {
        const double scale = args.heatmap_scale > 0.0 ? args.heatmap_scale : 2.0 * args.pixel_threshold;
        write_image(difference_heatmap(a, b, options, scale), args.heatmap);
        std::printf("  heatmap              %s (black 0 .. red >= %.4g)\n", args.heatmap.c_str(), scale);
    }
    if (over.empty()) {
        std::printf("within tolerance\n");
        return 0;
    }
    std::printf("OVER tolerance:");
    for (const auto& o : over) std::printf(" [%s]", o.c_str());
    std::printf("\n");
    return 1;
}

}  // namespace

void add_diff_command(CLI::App& app, int& exit_code) {
    auto args = std::make_shared<DiffArgs>();
    auto* cmd = app.add_subcommand(
        "diff",
        "Compare two images (.png, .pfm, .exr). Exit 0 within tolerance, 1 over it, 2 on bad input.\n"
        "Differences are taken per channel in display space (clamped to [0,1], sRGB-encoded, as a PNG\n"
        "holds them) unless --linear. The defaults accept 8-bit rounding and small noise and reject a\n"
        "visibly different picture; for Monte Carlo renders against a golden use --noise.");
    cmd->add_option("A", args->a, "First image")->required();
    cmd->add_option("B", args->b, "Second image (the reference)")->required();
    cmd->add_option("--heatmap", args->heatmap, "Write a false-colour PNG of each pixel's largest channel difference");
    cmd->add_option("--heatmap-scale", args->heatmap_scale, "Difference shown as full red (default: 2 x pixel threshold)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--max-rmse", args->max_rmse, "Largest accepted RMSE")->capture_default_str()->check(CLI::NonNegativeNumber);
    cmd->add_option("--max-share", args->max_share, "Largest accepted share (0..1) of pixels over the pixel threshold")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 1.0));
    cmd->add_option("--pixel-threshold", args->pixel_threshold, "A pixel differs when a channel differs by more")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--max-delta-e", args->max_delta_e,
                    "Largest accepted mean delta E of the blurred CIELAB metric (default: not checked)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--noise", args->noise,
                    "A second render of A with another seed and the same spp (.pfm/.exr: unclamped): also run the "
                    "noise-aware block z-test of mean(A, NOISE) against B (the image tests' criterion; 8x8 blocks, "
                    "family-wise false alarm 1e-4)");
    cmd->add_flag("--linear", args->linear, "Compare linear values, unclamped (HDR .pfm/.exr)");
    cmd->callback([args, &exit_code] { exit_code = run_diff(*args); });
}

}  // namespace sweeptrace
