// `sweeptrace noise-bench [SCENES...] [--pairs N] [--width W] [--alpha A]`: the false-alarm rate of
// `diff --variance-a/-b` measured on correct renders. For each scene and each spp of 4, 16, 64,
// N pairs of renders that differ only by seed (2k and 2k + 1), each with its own per-pixel
// variance of the pixel mean from the same samples, go through the same block z-test `diff`
// runs (8 x 8 blocks, family-wise rate alpha over all blocks and channels). It prints the share
// of pairs rejected per scene and spp, and whether it is within 2 alpha (the target of issue
// #14). A measurement, not a test: it asserts nothing and its exit code is 0 unless the input
// is bad.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "raytracer/accel/accel.hpp"
#include "raytracer/cli/commands.hpp"
#include "raytracer/image/diff.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/render/renderer.hpp"
#include "raytracer/scene/load_scene.hpp"

namespace sweeptrace {
namespace {

struct NoiseBenchArgs {
    std::vector<std::string> scenes;
    int pairs = 200;
    int width = 32;
    int threads = 0;
    double alpha = 0.01;
};

RenderResult render_seed(const Scene& scene, const Accel& accel, int spp, std::uint64_t seed, int threads) {
    RenderOptions o;
    o.spp = spp;
    o.max_depth = scene.film.max_depth;
    o.threads = threads;
    o.seed = seed;
    return render(scene, accel, o);
}

// Rejected pairs out of `pairs` at this spp.
int false_alarms(const Scene& scene, const Accel& accel, int spp, const NoiseBenchArgs& args) {
    int rejected = 0;
    for (int k = 0; k < args.pairs; ++k) {
        const RenderResult a = render_seed(scene, accel, spp, 2u * k + 1000u, args.threads);
        const RenderResult b = render_seed(scene, accel, spp, 2u * k + 1001u, args.threads);
        Image variance = a.variance;
        for (std::size_t i = 0; i < variance.pixels.size(); ++i) variance.pixels[i] += b.variance.pixels[i];
        BlockTestOptions o;
        o.golden_is_8bit = false;
        o.false_alarm = args.alpha;
        rejected += !block_test(b.image, a.image, variance, o).pass();
    }
    return rejected;
}

int run_noise_bench(NoiseBenchArgs args) {
    if (args.scenes.empty()) {  // every shipped scene
        for (const auto& e : std::filesystem::directory_iterator(SWEEPTRACE_SCENES_DIR))
            if (e.path().extension() == ".json") args.scenes.push_back(e.path().string());
        std::sort(args.scenes.begin(), args.scenes.end());
    }
    std::printf("false alarms of diff --variance-a/-b on seed pairs: %d pairs per row, alpha %g (target <= %g), "
                "8x8 blocks, width %d\n",
                args.pairs, args.alpha, 2.0 * args.alpha, args.width);
    std::printf("%-16s %8s %5s %9s %9s %s\n", "scene", "size", "spp", "rejected", "rate", "within 2 alpha");
    for (const std::string& path : args.scenes) {
        Scene scene = load_scene(path);
        const int w = scene.film.width, h = scene.film.height;
        scene.film.width = args.width;
        scene.film.height = std::max(1, static_cast<int>(std::lround(double(args.width) * h / w)));
        const std::unique_ptr<Accel> accel = make_accel(AccelKind::Bvh, scene);
        for (const int spp : {4, 16, 64}) {
            const int rejected = false_alarms(scene, *accel, spp, args);
            const double rate = double(rejected) / args.pairs;
            const std::string size = std::to_string(scene.film.width) + "x" + std::to_string(scene.film.height);
            std::printf("%-16s %8s %5d %5d/%-3d %9.4f %s\n", std::filesystem::path(path).stem().string().c_str(),
                        size.c_str(), spp, rejected, args.pairs, rate, rate <= 2.0 * args.alpha ? "yes" : "NO");
            std::fflush(stdout);
        }
    }
    return 0;
}

}  // namespace

void add_noise_bench_command(CLI::App& app, int& exit_code) {
    auto args = std::make_shared<NoiseBenchArgs>();
    auto* cmd = app.add_subcommand("noise-bench",
                                   "Measure the false-alarm rate of `diff --variance-a/-b` on renders differing only "
                                   "by seed (every shipped scene at 4, 16, 64 spp). Prints; asserts nothing.");
    cmd->add_option("scenes", args->scenes, "Scene files (default: every scene in scenes/)");
    cmd->add_option("--pairs", args->pairs, "Seed pairs per scene and spp")->capture_default_str()->check(CLI::PositiveNumber);
    cmd->add_option("--width", args->width, "Image width (height keeps the scene's aspect)")->capture_default_str()
        ->check(CLI::Range(8, 1024));
    cmd->add_option("--threads", args->threads, "Worker threads, 0 = all cores")->capture_default_str();
    cmd->add_option("--alpha", args->alpha, "Family-wise false-alarm rate of the test")->capture_default_str()
        ->check(CLI::Range(1e-9, 0.5));
    cmd->callback([args, &exit_code] { exit_code = run_noise_bench(*args); });
}

}  // namespace sweeptrace
