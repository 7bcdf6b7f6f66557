#include "raytracer/accuracy/sampling_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iterator>

#include "raytracer/accel/accel.hpp"
#include "raytracer/accuracy/thread_timer.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/render/renderer.hpp"
#include "raytracer/scene/load_scene.hpp"

namespace sweeptrace::accuracy {

namespace {

constexpr int kBorder = 3;  // pixels this close to an edge are left out (the "interior")
constexpr int kStudySpp[] = {16, 64, 256, 1024};

struct Config {
    const char* sampler_name;
    SamplerKind sampler;
    const char* roulette_name;
    RoulettePolicy roulette;
};
constexpr Config kConfigs[] = {
    {"independent", SamplerKind::Independent, "classic", RoulettePolicy::classic()},
    {"independent", SamplerKind::Independent, "adaptive", RoulettePolicy::adaptive()},
    {"sobol", SamplerKind::Sobol, "classic", RoulettePolicy::classic()},
    {"sobol", SamplerKind::Sobol, "adaptive", RoulettePolicy::adaptive()},
};

// The candidates the default roulette was chosen from (docs/sampling.md).
constexpr RoulettePolicy kRouletteCandidates[] = {
    RoulettePolicy::classic(), {3, 1.0f, true}, {2, 1.0f, true}, {5, 1.0f, true},
    {3, 0.5f, true},           {3, 0.25f, true}, {5, 0.25f, true}, {3, 0.1f, true},
};

struct Timed {
    RenderResult result;
    double seconds = 0.0;
};

Timed render_timed(const Scene& scene, const Accel& accel, int spp, SamplerKind sampler, RoulettePolicy roulette,
                   std::uint64_t seed, int threads) {
    RenderOptions o;
    o.spp = spp;
    o.max_depth = scene.film.max_depth;
    o.seed = seed;
    o.threads = threads;
    o.sampler = sampler;
    o.roulette = roulette;
    Timed t;
    const double start = process_seconds();
    t.result = render(scene, accel, o);
    t.seconds = process_seconds() - start;
    return t;
}

template <class F>
double interior_mean(const Image& image, F&& per_channel) {
    double sum = 0.0;
    std::size_t n = 0;
    for (int y = kBorder; y < image.height - kBorder; ++y)
        for (int x = kBorder; x < image.width - kBorder; ++x)
            for (int c = 0; c < 3; ++c, ++n) sum += per_channel(x, y, c);
    return n > 0 ? sum / double(n) : 0.0;
}

double interior_rmse(const Image& img, const RenderResult& ref) {
    const double mse = interior_mean(img, [&](int x, int y, int c) {
        const double d = double(img.at(x, y)[c]) - double(ref.image.at(x, y)[c]);
        return d * d - double(ref.variance.at(x, y)[c]);
    });
    return std::sqrt(std::max(mse, 0.0));
}

std::string file_hash(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    char buf[32];
    std::snprintf(buf, sizeof buf, "%016zx", std::hash<std::string>{}(bytes));
    return buf;
}

// The converged reference, rendered once and kept under cache_dir (the build tree).
RenderResult reference_for(const std::filesystem::path& path, const Scene& scene, const Accel& accel, int spp,
                           const std::filesystem::path& cache_dir) {
    const std::string key = path.stem().string() + "-" + file_hash(path) + "-" + std::to_string(scene.film.width) +
                            "x" + std::to_string(scene.film.height) + "-d" + std::to_string(scene.film.max_depth) +
                            "-" + std::to_string(spp);
    const auto image_path = cache_dir / (key + ".exr"), variance_path = cache_dir / (key + "-variance.exr");
    RenderResult ref;
    if (std::filesystem::exists(image_path) && std::filesystem::exists(variance_path)) {
        ref.image = read_image(image_path);
        ref.variance = read_image(variance_path);
        return ref;
    }
    std::fprintf(stderr, "sampling: rendering the %d-spp reference of %s (cached as %s)\n", spp,
                 path.filename().string().c_str(), image_path.string().c_str());
    ref = render_timed(scene, accel, spp, SamplerKind::Independent, RoulettePolicy::classic(), 777, 0).result;
    std::filesystem::create_directories(cache_dir);
    write_image(ref.image, image_path);
    write_image(ref.variance, variance_path);
    return ref;
}

double fitted_slope(const std::vector<SamplingRow>& rows) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double n = double(rows.size());
    for (const auto& r : rows) {
        const double x = std::log(double(r.spp)), y = std::log(std::max(r.rmse, 1e-30));
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

void study_configs(const std::string& name, const Scene& scene, const Accel& accel, const RenderResult& ref,
                   std::vector<SamplingRow>& out) {
    std::vector<SamplingRow> today;
    for (const Config& c : kConfigs) {
        std::vector<SamplingRow> rows;
        for (int spp : kStudySpp) {
            const Timed t = render_timed(scene, accel, spp, c.sampler, c.roulette, 1, 1);
            SamplingRow row{name, c.sampler_name, c.roulette_name, spp, t.seconds, interior_rmse(t.result.image, ref)};
            rows.push_back(row);
        }
        if (today.empty()) today = rows;
        const double slope = fitted_slope(rows);
        for (std::size_t i = 0; i < rows.size(); ++i) {
            rows[i].slope = slope;
            rows[i].equal_time = (rows[i].rmse / today[i].rmse) * std::sqrt(rows[i].seconds / today[i].seconds);
            out.push_back(rows[i]);
        }
    }
}

void study_roulette(const std::string& name, const Scene& scene, const Accel& accel, int spp,
                    std::vector<RouletteRow>& out) {
    double classic = 0.0;
    const double samples = double(scene.film.width) * scene.film.height * spp;
    for (const RoulettePolicy& p : kRouletteCandidates) {
        const Timed t = render_timed(scene, accel, spp, SamplerKind::Independent, p, 1, 1);
        RouletteRow row{name, p};
        row.per_sample_variance = interior_mean(
            t.result.variance, [&](int x, int y, int c) { return double(t.result.variance.at(x, y)[c]) * spp; });
        row.us_per_sample = 1e6 * t.seconds / samples;
        row.product = row.per_sample_variance * row.us_per_sample;
        if (classic == 0.0) classic = row.product;
        row.relative = row.product / classic;
        out.push_back(row);
    }
}

}  // namespace

SamplingReport sampling_study(const std::vector<std::filesystem::path>& scenes, int size, int reference_spp,
                              int roulette_spp, const std::filesystem::path& cache_dir, bool convergence) {
    SamplingReport report;
    report.width = size;
    report.reference_spp = reference_spp;
    report.roulette_spp = roulette_spp;
    for (const auto& path : scenes) {
        Scene scene = load_scene(path);
        const int w = scene.film.width, h = scene.film.height;
        scene.film.width = size;
        scene.film.height = std::max(2 * kBorder + 1, size * h / std::max(1, w));
        const auto accel = make_accel(AccelKind::Bvh, scene);
        const std::string name = path.stem().string();
        if (convergence) {
            const RenderResult ref = reference_for(path, scene, *accel, reference_spp, cache_dir);
            study_configs(name, scene, *accel, ref, report.rows);
        }
        if (roulette_spp > 0) study_roulette(name, scene, *accel, roulette_spp, report.roulette);
    }
    return report;
}

namespace {

std::string policy_text(const RoulettePolicy& p) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "from vertex %d, below %.2g%s", p.start_depth, double(p.threshold),
                  p.undo_refraction_scale ? ", eta undone" : "");
    return buf;
}

void write_convergence_rows(std::ostream& out, const SamplingReport& r) {
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  "%d px wide, 1 thread, CPU seconds; RMSE over pixels > %d px from the edges against a %d-spp "
                  "reference (its own noise removed); equal-time = RMSE ratio against independent + classic at "
                  "the same CPU time.\n\n",
                  r.width, kBorder, r.reference_spp);
    out << buf;
    out << "| scene | sampler | roulette | spp | CPU s | RMSE | equal-time vs today | slope 16-1024 |\n"
           "|---|---|---|---:|---:|---:|---:|---:|\n";
    for (const auto& row : r.rows) {
        std::snprintf(buf, sizeof buf, "| %s | %s | %s | %d | %.3g | %.4g | %.3f | %.3f |\n", row.scene.c_str(),
                      row.sampler.c_str(), row.roulette.c_str(), row.spp, row.seconds, row.rmse, row.equal_time,
                      row.slope);
        out << buf;
    }
}

void write_roulette_rows(std::ostream& out, const SamplingReport& r) {
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  "\nRoulette candidates, %d px wide, independent sampler, %d spp, 1 thread: per-sample variance "
                  "(mean over interior pixels and channels) x CPU microseconds per sample.\n\n",
                  r.width, r.roulette_spp);
    out << buf;
    out << "| scene | policy | per-sample variance | us/sample | variance x time | relative to classic |\n"
           "|---|---|---:|---:|---:|---:|\n";
    for (const auto& row : r.roulette) {
        std::snprintf(buf, sizeof buf, "| %s | %s | %.4g | %.3g | %.4g | %.3f |\n", row.scene.c_str(),
                      policy_text(row.policy).c_str(), row.per_sample_variance, row.us_per_sample, row.product,
                      row.relative);
        out << buf;
    }
}

}  // namespace

void write_sampling_markdown(std::ostream& out, const SamplingReport& r) {
    if (!r.rows.empty()) write_convergence_rows(out, r);
    if (!r.roulette.empty()) write_roulette_rows(out, r);
}

void write_sampling_csv(std::ostream& out, const SamplingReport& r) {
    out << "table,scene,sampler,roulette,spp,seconds,rmse,equal_time,slope,variance,us_per_sample,product,relative\n";
    char buf[320];
    for (const auto& row : r.rows) {
        std::snprintf(buf, sizeof buf, "convergence,%s,%s,%s,%d,%.6g,%.6g,%.6g,%.6g,,,,\n", row.scene.c_str(),
                      row.sampler.c_str(), row.roulette.c_str(), row.spp, row.seconds, row.rmse, row.equal_time,
                      row.slope);
        out << buf;
    }
    for (const auto& row : r.roulette) {
        std::snprintf(buf, sizeof buf, "roulette,%s,independent,\"%s\",%d,,,,,%.6g,%.6g,%.6g,%.6g\n", row.scene.c_str(),
                      policy_text(row.policy).c_str(), r.roulette_spp, row.per_sample_variance, row.us_per_sample,
                      row.product, row.relative);
        out << buf;
    }
}

}  // namespace sweeptrace::accuracy
