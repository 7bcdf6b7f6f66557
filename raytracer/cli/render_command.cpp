// `sweeptrace render SCENE.json [options]`: load, build the acceleration structure, render with a
// progress display, write the image atomically. Ctrl-C or SIGTERM stops after the samples
// finished so far, writes them, and exits 130 / 143; a second signal kills at once (the atomic
// write still leaves no partial file, cli/interrupt.hpp).
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <tbb/info.h>

#include "raytracer/accel/accel.hpp"
#include "raytracer/cli/commands.hpp"
#include "raytracer/cli/interrupt.hpp"
#include "raytracer/cli/memory_budget.hpp"
#include "raytracer/cli/output_guard.hpp"
#include "raytracer/cli/render_limits.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/render/renderer.hpp"
#include "raytracer/render/tone_map.hpp"
#include "raytracer/scene/load_scene.hpp"

namespace sweeptrace {

namespace {

struct RenderArgs {
    std::string scene;
    std::string output;
    RenderLimits limits;  // --width --height --spp --max-depth --seed --threads --max-memory
    std::string accel = "bvh";
    bool quiet = false;
};

std::string clock_text(double seconds) {
    const auto s = static_cast<long>(std::lround(std::max(0.0, seconds)));
    char buf[32];
    if (s >= 3600) std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
    else std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
    return buf;
}

std::string si_text(double v) {
    char buf[32];
    if (v >= 1e9) std::snprintf(buf, sizeof buf, "%.2fG", v / 1e9);
    else if (v >= 1e6) std::snprintf(buf, sizeof buf, "%.2fM", v / 1e6);
    else if (v >= 1e3) std::snprintf(buf, sizeof buf, "%.1fk", v / 1e3);
    else std::snprintf(buf, sizeof buf, "%.0f", v);
    return buf;
}

// On a terminal: one bar redrawn in place with elapsed time and ETA. Otherwise (a log, CI): a
// plain line at each 10%.
class ProgressDisplay {
public:
    explicit ProgressDisplay(bool tty) : tty_(tty), start_(std::chrono::steady_clock::now()) {}

    void update(double fraction) {
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        if (tty_) {
            constexpr int kWidth = 30;
            const int filled = static_cast<int>(fraction * kWidth);
            std::string bar(static_cast<std::size_t>(filled), '#');
            bar.resize(kWidth, '.');
            const std::string eta = fraction > 0.0 ? clock_text(elapsed * (1.0 - fraction) / fraction) : "?";
            std::fprintf(stderr, "\r[%s] %3d%%  elapsed %s  ETA %s ", bar.c_str(), static_cast<int>(fraction * 100.0),
                         clock_text(elapsed).c_str(), eta.c_str());
            std::fflush(stderr);
            drawn_ = true;
        } else {
            const int tenth = static_cast<int>(fraction * 10.0 + 1e-9);
            while (printed_tenths_ < tenth) {
                ++printed_tenths_;
                std::fprintf(stderr, "render: %d%% (%s elapsed)\n", printed_tenths_ * 10, clock_text(elapsed).c_str());
            }
        }
    }
    void finish() {
        if (tty_ && drawn_) std::fputc('\n', stderr);
    }

private:
    bool tty_;
    std::chrono::steady_clock::time_point start_;
    bool drawn_ = false;
    int printed_tenths_ = 0;
};

void require(bool ok, const std::string& message) {
    if (!ok) throw InputError(message);
}

int run_render(const RenderArgs& a) {
    a.limits.validate();
    const int thread_count = a.limits.thread_count();

    const std::filesystem::path scene_path(a.scene);
    const std::filesystem::path out =
        a.output.empty() ? std::filesystem::path(scene_path.stem().string() + ".png") : std::filesystem::path(a.output);
    {
        // Fail before a long render, not after it.
        std::string ext = out.extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        require(ext == ".png" || ext == ".pfm" || ext == ".exr",
                "output '" + out.string() + "': unknown image extension '" + ext + "' (use .png, .pfm or .exr)");
        const std::filesystem::path dir = out.parent_path();
        std::error_code ec;
        require(dir.empty() || std::filesystem::is_directory(dir, ec),
                "output '" + out.string() + "': directory '" + dir.string() + "' does not exist");
    }

    Scene scene = load_scene(scene_path);
    a.limits.apply(scene);
    std::vector<NamedInput> inputs{{"scene", scene_path}};
    for (const Mesh& m : scene.meshes) inputs.push_back({"mesh", m.source});
    refuse_output_over_input(out, inputs);
    check_render_memory(scene, a.limits.memory_limit());

    const auto build_start = std::chrono::steady_clock::now();
    const std::unique_ptr<Accel> accel = make_accel(a.accel == "embree" ? AccelKind::Embree : AccelKind::Bvh, scene);
    const double build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - build_start).count();

    RenderOptions opt;
    opt.spp = scene.film.spp;
    opt.max_depth = scene.film.max_depth;
    opt.threads = thread_count;
    opt.seed = scene.seed;
    const InterruptGuard interrupt;
    opt.cancel = InterruptGuard::flag();
    ProgressDisplay progress(isatty(fileno(stderr)) != 0);
    if (!a.quiet) opt.progress = [&progress](double f) { progress.update(f); };

    const RenderResult result = render(scene, *accel, opt);
    if (!a.quiet) progress.finish();

    const RenderStats& st = result.stats;
    if (st.nonfinite_samples > 0)
        std::fprintf(stderr, "sweeptrace: warning: %llu samples had non-finite radiance and were counted as black\n",
                     static_cast<unsigned long long>(st.nonfinite_samples));
    if (st.cancelled && st.completed_spp == 0) {
        std::fprintf(stderr, "sweeptrace: interrupted before the first pass over the image finished; nothing written\n");
        return InterruptGuard::exit_code();
    }
    write_image(is_display_format(out) ? to_display(result.image) : result.image, out);
    if (st.cancelled)
        std::fprintf(stderr, "sweeptrace: interrupted: wrote %s with %d of %d samples per pixel\n", out.string().c_str(),
                     st.completed_spp, opt.spp);
    if (!a.quiet) {
        const int threads = thread_count > 0 ? thread_count : tbb::info::default_concurrency();
        const double secs = std::max(st.seconds, 1e-9);
        std::fprintf(stderr,
                     "%s: %dx%d, %d spp, %s (%s, built in %.2f s), %d thread%s: %.2f s, %s samples/s, %s rays/s -> %s\n",
                     scene_path.filename().string().c_str(), scene.film.width, scene.film.height, st.completed_spp,
                     accel->name().c_str(), si_text(double(accel->memory_bytes())).append("B").c_str(), build_seconds,
                     threads, threads == 1 ? "" : "s", st.seconds, si_text(double(st.samples) / secs).c_str(),
                     si_text(double(st.rays) / secs).c_str(), out.string().c_str());
    }
    return st.cancelled ? InterruptGuard::exit_code() : 0;
}

}  // namespace

void add_render_command(CLI::App& app, int& exit_code) {
    auto args = std::make_shared<RenderArgs>();
    auto* cmd = app.add_subcommand("render", "Render a JSON scene to an image");
    cmd->add_option("scene", args->scene, "Scene file (JSON, see scenes/README.md)")->required();
    cmd->add_option("-o,--output", args->output,
                    "Output image: .png (8-bit sRGB, radiance clamped to [0, 1]), .pfm or .exr (linear float). "
                    "Default: the scene's name with .png, in the current directory");
    args->limits.add_options(*cmd);
    cmd->add_option("--accel", args->accel, "Acceleration structure")
        ->check(CLI::IsMember({"bvh", "embree"}))
        ->capture_default_str();
    cmd->add_flag("--quiet", args->quiet, "No progress display and no summary");
    cmd->callback([args, &exit_code] { exit_code = run_render(*args); });
}

}  // namespace sweeptrace
