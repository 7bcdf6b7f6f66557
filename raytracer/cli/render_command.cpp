// `sweeptrace render SCENE.json|SCENE.pbrt [options]`: load (a .pbrt through the pbrt-v4 importer), build the acceleration structure, render with a
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
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <tbb/info.h>

#include "raytracer/accel/accel.hpp"
#include "raytracer/cli/aov_outputs.hpp"
#include "raytracer/cli/commands.hpp"
#include "raytracer/cli/denoise_image.hpp"
#include "raytracer/cli/render_identity.hpp"
#include "raytracer/cli/render_part.hpp"
#include "raytracer/cli/interrupt.hpp"
#include "raytracer/cli/memory_budget.hpp"
#include "raytracer/cli/output_guard.hpp"
#include "raytracer/cli/render_limits.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/image/atomic_file.hpp"
#include "raytracer/render/film/path_forensics.hpp"
#include "raytracer/load_budget.hpp"
#include "raytracer/render/renderer.hpp"
#include "raytracer/render/film/tone_map.hpp"
#include "raytracer/scene/emitter_check.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "raytracer/scene/pbrt/pbrt_import.hpp"

namespace sweeptrace {

namespace {

// --time without --spp: no pass limit a render could reach (the scene format's own spp limit).
constexpr int kMaxTimedSpp = 1 << 20;

struct RenderArgs {
    std::string scene;
    std::string output;
    std::string variance;  // optional: per-pixel variance of the pixel means (float formats only)
    std::string forensics;  // optional: noise forensics report (.json), its picture beside it
    RenderLimits limits;   // --width --height --spp --max-depth --seed --threads --max-memory
    double time = 0.0;
    std::string accel = "bvh";
    std::string sampler;  // empty: the scene's film.sampler
    std::string guiding;  // "on", "off" or empty: the scene's film.guiding
    std::string integrator;  // "path", "bdpt", "vcm" or empty: the scene's film.integrator
    std::string adaptive = "off";  // adaptive sampling (render/adaptive_sampling.hpp): "on" (Mse), "relative" or "off"
    std::string time_clock = "wall";
    bool quiet = false;
    std::string samples;  // "A:B": render a farm part
    CLI::Option* samples_opt = nullptr;  // given at all: "--samples ''" is a bad range, not a whole render
    bool skip_existing = false;
    bool strict = false;  // a .pbrt scene: anything approximated or ignored is an error
    bool aovs = false;    // feature outputs (cli/aov_outputs.hpp); also the scene's film.aovs
    std::string denoise;  // --denoise FILE: NFOR on the feature image -o writes (cli/denoise_image.hpp)
    CLI::Option* time_opt = nullptr;
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

// On a terminal: one bar redrawn in place with elapsed time, time left (the ETA, or what is left
// of --time), the spp reached and samples/s. Otherwise (a log, CI): a plain line at each 10%.
class ProgressDisplay {
public:
    ProgressDisplay(bool tty, std::uint64_t pixels) : tty_(tty), pixels_(pixels) {}

    void update(const RenderProgress& p) {
        if (tty_) {
            constexpr int kWidth = 30;
            const int filled = static_cast<int>(p.fraction * kWidth);
            std::string bar(static_cast<std::size_t>(filled), '#');
            bar.resize(kWidth, '.');
            std::string left = "?";
            if (p.seconds_left >= 0.0) left = clock_text(p.seconds_left);
            else if (p.fraction > 0.0) left = clock_text(p.seconds * (1.0 - p.fraction) / p.fraction);
            const std::string rate =
                p.completed_spp > 0 ? si_text(double(p.completed_spp) * double(pixels_) / std::max(p.seconds, 1e-9)) : "?";
            std::fprintf(stderr, "\r[%s] %3d%%  elapsed %s  left %s  %d spp  %s samples/s ", bar.c_str(),
                         static_cast<int>(p.fraction * 100.0), clock_text(p.seconds).c_str(), left.c_str(),
                         p.completed_spp, rate.c_str());
            std::fflush(stderr);
            drawn_ = true;
        } else {
            const int tenth = static_cast<int>(p.fraction * 10.0 + 1e-9);
            while (printed_tenths_ < tenth) {
                ++printed_tenths_;
                std::fprintf(stderr, "render: %d%% (%s elapsed, %d spp)\n", printed_tenths_ * 10,
                             clock_text(p.seconds).c_str(), p.completed_spp);
            }
        }
    }
    void finish() {
        if (tty_ && drawn_) std::fputc('\n', stderr);
    }

private:
    bool tty_;
    std::uint64_t pixels_;
    bool drawn_ = false;
    int printed_tenths_ = 0;
};

// The picture of a forensics report: beside it, `NAME-regions.png` for `NAME.json`.
std::filesystem::path forensics_picture(const std::filesystem::path& report) {
    std::filesystem::path p = report;
    return p.replace_filename(report.stem().string() + "-regions.png");
}

void require(bool ok, const std::string& message) {
    if (!ok) throw InputError(message);
}

// Every file the render writes, for the one output rule (output_guard.hpp); a new output joins
// it here.
std::vector<NamedFile> render_outputs(const RenderArgs& a, const std::filesystem::path& out) {
    std::vector<NamedFile> outputs{{"output", out}};
    if (!a.variance.empty()) outputs.push_back({"--variance", a.variance});
    if (!a.forensics.empty()) {
        outputs.push_back({"--forensics", a.forensics});
        outputs.push_back({"--forensics picture", forensics_picture(a.forensics)});
    }
    if (!a.denoise.empty()) outputs.push_back({"--denoise", a.denoise});
    return outputs;
}

int run_render(const RenderArgs& a) {
    a.limits.validate();
    const bool part = a.samples_opt->count() > 0;
    const int thread_count = a.limits.thread_count();
    if (a.time_opt->count())
        require(a.time > 0.0 && std::isfinite(a.time), "--time must be a positive number of seconds, got " + a.time_opt->as<std::string>());

    const std::filesystem::path scene_path(a.scene);
    set_load_memory_limit(a.limits.memory_limit());  // the load's budget (load_budget.hpp) as the render's
    // A pbrt-v4 scene is translated first (cheap next to a render): its Film's filename is the
    // default output, as in pbrt, and its warnings come before the render starts.
    const bool pbrt = is_pbrt_file(scene_path);
    std::optional<Scene> pbrt_scene;
    std::string film_filename;
    if (pbrt) {
        std::vector<std::string> warnings;
        pbrt_scene.emplace(load_pbrt_scene(scene_path, a.strict, warnings, &film_filename));
        for (const std::string& w : warnings) std::fprintf(stderr, "sweeptrace: warning: %s\n", escape_control(w).c_str());
    } else {
        require(!a.strict, "--strict is for .pbrt scenes (a JSON scene never approximates)");
    }
    const std::filesystem::path out =
        !a.output.empty() ? std::filesystem::path(a.output)
        : pbrt            ? std::filesystem::path(film_filename)
                          : std::filesystem::path(scene_path.stem().string() + ".png");
    {
        // Fail before a long render, not after it.
        std::string ext = out.extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        require(ext == ".png" || ext == ".pfm" || ext == ".exr",
                "output '" + out.string() + "': unknown image extension '" + ext + "' (use .png, .pfm or .exr)");
        require(!part || ext == ".exr", "--samples writes a farm part, an .exr file; got '" + out.string() + "'");
        require(!a.skip_existing || part, "--skip-existing needs --samples");
        if (!a.variance.empty()) {
            std::string vext = std::filesystem::path(a.variance).extension().string();
            std::transform(vext.begin(), vext.end(), vext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
            require(vext == ".pfm" || vext == ".exr", "--variance '" + a.variance + "': use .exr or .pfm (variances are not 8-bit colours)");
        }
        require(a.forensics.empty() || std::filesystem::path(a.forensics).extension() == ".json",
                "--forensics '" + a.forensics + "': the report is a .json file");
        if (!a.denoise.empty()) {
            // The raw render stays: it is the feature image -o names, and the denoised one goes beside it.
            require(a.samples.empty(), "--denoise makes a whole image: merge the farm parts, then run sweeptrace denoise on the result");
            require(lowercase_extension(out) == ".exr",
                    "--denoise needs -o OUT.exr: the feature image NFOR reads, kept beside the denoised image; got '" + out.string() + "'");
            check_denoise_output(a.denoise);
        }
    }
    const std::vector<NamedFile> outputs = render_outputs(a, out);
    check_outputs(outputs, {{"scene", scene_path}});  // the outputs' own clashes, before the load

    Scene scene = pbrt ? std::move(*pbrt_scene) : load_scene(scene_path);
    for (const std::string& w : emitters_facing_nothing(scene)) std::fprintf(stderr, "sweeptrace: warning: %s\n", escape_control(w).c_str());
    a.limits.apply(scene);
    if (a.aovs || !a.denoise.empty()) scene.film.aovs = true;
    if (!a.sampler.empty())
        scene.film.sampler = a.sampler == "independent"    ? SamplerKind::Independent
                             : a.sampler == "sobol-halves" ? SamplerKind::SobolHalves
                                                           : SamplerKind::Sobol;
    // Half buffers are NFOR's error estimate, which takes them for independent: the scene's Sobol
    // sampler becomes its halves form. Only --sampler sobol, said on this command line, keeps one
    // sequence split in two (docs/aovs.md, "Independent halves").
    else if (scene.film.aovs && scene.film.sampler == SamplerKind::Sobol)
        scene.film.sampler = SamplerKind::SobolHalves;
    if (!a.integrator.empty())
        scene.film.integrator = a.integrator == "vcm"    ? IntegratorKind::Vcm
                                : a.integrator == "bdpt" ? IntegratorKind::Bdpt
                                                         : IntegratorKind::Path;
    // Every file the load read (the scene's own list, read_files.hpp), before any work starts.
    std::vector<NamedFile> inputs{{"scene", scene_path}};
    for (const std::filesystem::path& f : scene.input_files) inputs.push_back({"scene's input", f});
    std::vector<NamedFile> all_outputs = outputs;
    if (scene.film.aovs && !part) add_aov_outputs(all_outputs, out);  // a farm part keeps its feature sums in itself
    check_outputs(all_outputs, inputs);
    check_render_memory(scene, a.limits.memory_limit(), a.adaptive != "off", !a.forensics.empty());
    if (!a.denoise.empty()) check_denoise_memory("--denoise '" + a.denoise + "'", scene.film.width, scene.film.height, thread_count);

    // A farm part: which samples, and the render they belong to; a re-run task skips a finished one.
    const SampleRange range =
        !part ? SampleRange{0, scene.film.spp} : parse_sample_range(a.samples, scene.film.spp);
    const RenderIdentity identity = !part ? RenderIdentity{} : render_identity(scene, scene_path, a.accel, a.adaptive);
    if (a.skip_existing && is_finished_part(out, identity, range)) {
        if (!a.quiet) std::fprintf(stderr, "%s: already a verified part of this render, kept\n", out.string().c_str());
        return 0;
    }

    const auto build_start = std::chrono::steady_clock::now();
    const std::unique_ptr<Accel> accel = make_accel(a.accel == "embree" ? AccelKind::Embree : AccelKind::Bvh, scene);
    const double build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - build_start).count();

    RenderOptions opt;
    // --time alone renders until the budget is spent; with --spp, whichever comes first.
    opt.spp = a.time_opt->count() && !a.limits.spp_opt->count() ? kMaxTimedSpp : scene.film.spp;
    opt.time_budget = a.time_opt->count() ? a.time : 0.0;
    opt.budget_clock = a.time_clock == "cpu" ? BudgetClock::ProcessCpu : BudgetClock::Wall;
    opt.max_depth = scene.film.max_depth;
    opt.threads = thread_count;
    opt.seed = scene.seed;
    opt.sampler = scene.film.sampler;
    opt.integrator = scene.film.integrator;
    // Guiding is the path tracer's: a scene that asks for it is rendered unguided by bdpt, and
    // asking for both on the command line is an error.
    require(!(a.guiding == "on" && opt.integrator != IntegratorKind::Path), "--guiding on needs the path integrator");
    require(a.forensics.empty() || opt.integrator == IntegratorKind::Path,
            "--forensics needs the path integrator: it follows a camera path's vertices, and the light paths of bdpt and vcm have none of them");
    opt.guiding = opt.integrator == IntegratorKind::Path && (a.guiding.empty() ? scene.film.guiding : a.guiding == "on");
    opt.adaptive = a.adaptive != "off";
    opt.aovs = scene.film.aovs;
    opt.adaptive_error = a.adaptive == "relative" ? AdaptiveError::Relative : AdaptiveError::Mse;
    if (opt.adaptive) {
        // A farm part (--samples) needs nothing more: its samples follow from the pilot, which it
        // renders itself (renderer.cpp, run_adaptive).
        require(opt.integrator == IntegratorKind::Path,
                "--adaptive on needs the path integrator: the light paths of bdpt and vcm add to other pixels than the "
                "sample's, so a pixel's count of samples would not be its count of estimates");
        require(!opt.guiding, "--adaptive on needs guiding off (the scene's film.guiding or --guiding on): the guide "
                              "learns from whole passes over the image");
        require(a.forensics.empty(), "--adaptive on cannot be combined with --forensics: the report is per pass over the image");
    }
    if (opt.integrator != IntegratorKind::Path) {
        // The path tracer's biased firefly guard and its guide have no bdpt or vcm counterpart: say
        // what the scene asked for and is not getting, so a brighter or noisier image is no surprise.
        const char* name = opt.integrator == IntegratorKind::Vcm ? "vcm" : "bdpt";
        if (scene.film.clamp_indirect > 0.0f)
            std::fprintf(stderr, "sweeptrace: warning: %s: film.clamp_indirect %g is the path tracer's; %s ignores it "
                                 "(its image is the unclamped one)\n",
                         escape_control(scene_path.filename().string()).c_str(), double(scene.film.clamp_indirect), name);
        if (scene.film.guiding && a.guiding.empty())
            std::fprintf(stderr, "sweeptrace: warning: %s: film.guiding is the path tracer's; %s renders unguided\n",
                         escape_control(scene_path.filename().string()).c_str(), name);
    }
    if (part) {
        // A part must be exactly the samples [A, B) a whole render draws: a time budget would cut
        // it short, and a guided sample depends on the guide trained on every pass before it.
        require(!a.time_opt->count(), "--samples and --time cannot be combined: a farm part renders its whole range");
        require(!opt.guiding, "--samples needs --guiding off: a guided sample depends on the passes rendered before it");
        opt.first_sample = range.begin;
        opt.spp = range.end - range.begin;
    }
    const InterruptGuard interrupt;
    opt.cancel = InterruptGuard::flag();
    ProgressDisplay progress(isatty(fileno(stderr)) != 0, std::uint64_t(scene.film.width) * scene.film.height);
    if (!a.quiet) opt.progress = [&progress](const RenderProgress& p) { progress.update(p); };

    std::optional<PathForensics> forensics;
    if (!a.forensics.empty()) opt.forensics = &forensics.emplace(scene);
    const RenderResult result = render(scene, *accel, opt);
    if (!a.quiet) progress.finish();

    const RenderStats& st = result.stats;
    if (st.clamped_samples > 0)
        std::fprintf(stderr, "sweeptrace: warning: %llu sample channels were beyond 2^40 and were clamped to it\n",
                     static_cast<unsigned long long>(st.clamped_samples));
    if (st.nonfinite_samples > 0)
        std::fprintf(stderr, "sweeptrace: warning: %llu samples had non-finite radiance and were counted as black\n",
                     static_cast<unsigned long long>(st.nonfinite_samples));
    if (st.cancelled && st.completed_spp == 0) {
        std::fprintf(stderr, "sweeptrace: interrupted before the first pass over the image finished; nothing written\n");
        return InterruptGuard::exit_code();
    }
    if (part) write_part(result, identity, range.begin, out);
    else {
        const Image image = is_display_format(out) ? to_display(result.image, scene.film.exposure, scene.film.tone_curve) : result.image;
        if (opt.aovs) write_image_with_aovs(image, result.features, st.completed_spp, out);
        else write_image(image, out);
    }
    if (!a.variance.empty()) write_image(result.variance, a.variance);
    if (forensics) {
        const std::string text = forensics->json(st.completed_spp);
        write_atomically(a.forensics, [&](const std::filesystem::path& temp) {
            std::ofstream f(temp, std::ios::binary);
            f << text;
            if (!f) throw InputError("--forensics '" + a.forensics + "': could not write it");
        });
        write_image(forensics->picture(result.image), forensics_picture(a.forensics));
        std::fputs(forensics->table().c_str(), stdout);
        std::fflush(stdout);
    }
    if (st.cancelled)
        std::fprintf(stderr, "sweeptrace: interrupted: wrote %s with %d of %d samples per pixel\n", out.string().c_str(),
                     st.completed_spp, opt.spp);
    else if (!a.denoise.empty()) {
        const DenoiseReport d = denoise_file(out, a.denoise, thread_count);
        if (!a.quiet) std::fprintf(stderr, "%s -> %s (NFOR, %.2f s)\n", out.string().c_str(), a.denoise.c_str(), d.seconds);
    }
    if (st.budget_spent && !a.quiet)
        std::fprintf(stderr, "sweeptrace: --time %g s spent: %d spp reached\n", a.time, st.completed_spp);
    if (!a.quiet) {
        const int threads = thread_count > 0 ? thread_count : tbb::info::default_concurrency();
        const double secs = std::max(st.seconds, 1e-9);
        std::fprintf(stderr,
                     "%s: %dx%d, %d spp%s, %s (%s, built in %.2f s), %d thread%s: %.2f s, %s samples/s, %s rays/s -> %s\n",
                     scene_path.filename().string().c_str(), scene.film.width, scene.film.height, st.completed_spp,
                     opt.guiding                              ? " guided"
                     : opt.integrator != IntegratorKind::Path ? (std::string(" ") + integrator_name(opt.integrator)).c_str()
                     : opt.adaptive                           ? " adaptive (mean)"
                                                              : "",
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
    cmd->add_option("scene", args->scene,
                    "Scene file: JSON (scenes/README.md), or a pbrt-v4 scene (.pbrt, docs/pbrt-import.md), translated in memory")
        ->required();
    cmd->add_option("-o,--output", args->output,
                    "Output image: .png (8-bit sRGB: radiance x 2^film.exposure through film.tone_curve, by default clamped to [0, 1]), .pfm or .exr (linear float). "
                    "Default: the scene's name with .png, in the current directory (a .pbrt scene: its Film's filename, pbrt.exr if none)");
    cmd->add_option("--variance", args->variance,
                    "Also write the per-pixel variance of each pixel's mean (.exr/.pfm): the samples' unbiased "
                    "variance / the pixel's sample count (spp; under --adaptive its own), from the same samples (needs spp >= 2); for `diff --variance-a/-b`. Exact for "
                    "--sampler independent; under sobol (stratified) the true variance is smaller, so the file "
                    "overstates it and diff's noise test is conservative");
    cmd->add_option("--forensics", args->forensics,
                    "Noise forensics: also write FILE.json, which path types (L D S E ...), lights and materials carry "
                    "each 16x16 region's second moment, and FILE-regions.png, each region coloured by its dominant "
                    "path type; print the image's table (docs/noise-forensics.md). The image is unchanged");
    args->limits.add_options(*cmd);
    args->time_opt = cmd->add_option("--time", args->time,
                                     "Time budget in seconds (wall clock): whole passes of 1 spp until it is spent, at "
                                     "least one; the image holds the finished passes (--adaptive: after its pilot, passes of 8 spp on "
                                     "average). With --spp, whichever comes first");
    cmd->add_option("--accel", args->accel, "Acceleration structure")
        ->check(CLI::IsMember({"bvh", "embree"}))
        ->capture_default_str();
    cmd->add_option("--sampler", args->sampler,
                    "Sample numbers: sobol (Owen-scrambled Sobol, stratified), sobol-halves (two independently scrambled "
                    "Sobol sequences, one for the even and one for the odd samples: independent half buffers) or "
                    "independent (uniform random). Default: the scene's film.sampler, else sobol; with --aovs or "
                    "--denoise, a scene's sobol becomes sobol-halves (docs/aovs.md)")
        ->check(CLI::IsMember({"sobol", "sobol-halves", "independent"}));
    cmd->add_option("--time-clock", args->time_clock,
                    "What --time counts: wall seconds, or cpu seconds of all threads (equal-time comparisons on a "
                    "shared machine)")
        ->check(CLI::IsMember({"wall", "cpu"}))
        ->capture_default_str();
    cmd->add_option("--guiding", args->guiding,
                    "Path guiding (learned during the render, unbiased): on or off (default: the scene's film.guiding)")
        ->check(CLI::IsMember({"on", "off"}));
    cmd->add_option("--integrator", args->integrator,
                    "Light transport: path (unidirectional), bdpt (bidirectional) or vcm (vertex connection and merging) "
                    "(default: the scene's film.integrator)")
        ->check(CLI::IsMember({"path", "bdpt", "vcm"}));
    cmd->add_option("--adaptive", args->adaptive,
                    "Adaptive sampling: a 16-spp pilot, then each 8x8 tile's samples in proportion to a weight from the "
                    "pilot's error (1/8 of them spread evenly), so that each pixel gets 16 + round((N - 16) x its weight) "
                    "and the mean is within 1/2 of --spp N; with --time, passes of 8 spp on average until it is spent. on: "
                    "weight in proportion to the tile's standard deviation (least squared error of the linear image); "
                    "relative: to its relative variance (Tungsten's; favours dark tiles). Errors capped at the 95th "
                    "percentile; each pixel's weight from the other colour of a checkerboard, so unbiased. Same image at any thread count and from any --samples split (A:B then nominal spp; each "
                    "part renders the 16-spp pilot again); path integrator only, no guiding or --forensics "
                    "(docs/equal-time-interiors.md)")
        ->check(CLI::IsMember({"on", "relative", "off"}))
        ->capture_default_str();
    cmd->add_flag("--quiet", args->quiet, "No progress display and no summary");
    cmd->add_flag("--aovs", args->aovs,
                  "Feature outputs for a denoiser (also the scene's film.aovs): albedo, shading normal and depth at "
                  "the first non-specular vertex, their variances and the even/odd half buffers. With -o OUT.exr all "
                  "in that one EXR (pbrt-v4 gbuffer channel names: Albedo.R, Ns.X, P.Z, ...); with .png/.pfm beside it "
                  "OUT.albedo.pfm, OUT.normal.pfm, OUT.depth.pfm (docs/aovs.md)");
    cmd->add_option("--denoise", args->denoise,
                    "Also write FILE (.exr, .pfm or .png): the render denoised by NFOR from its features (implies --aovs; "
                    "-o must be an .exr, the feature image, which is kept; docs/denoising.md)");
    cmd->add_flag("--strict", args->strict,
                  "A .pbrt scene: refuse (exit 2) anything the translation would approximate or ignore, instead of a warning");
    args->samples_opt = cmd->add_option("--samples", args->samples,
                    "A:B: render only sample indices [A, B) of the --spp render, to a farm part (.exr) for "
                    "`sweeptrace merge` (with --adaptive: nominal spp, see there)");
    cmd->add_flag("--skip-existing", args->skip_existing,
                  "With --samples: keep the output if it already is this render's verified part for A:B");
    cmd->callback([args, &exit_code] { exit_code = run_render(*args); });
}

}  // namespace sweeptrace
