#include "golden_harness.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "raytracer/image/atomic_file.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/scene/load_scene.hpp"

namespace sweeptrace::testing {
namespace {

const std::filesystem::path source_dir = SWEEPTRACE_SOURCE_DIR;
const std::filesystem::path output_root = std::filesystem::path(SWEEPTRACE_BINARY_DIR) / "image-tests";

std::string html_escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '&') out += "&amp;";
        else out += c;
    }
    return out;
}

void write_text_atomically(const std::filesystem::path& path, const std::string& text) {
    write_atomically(path, [&](const std::filesystem::path& temp) {
        std::ofstream out(temp, std::ios::binary);
        out << text;
        if (!out) throw std::runtime_error("cannot write " + temp.string());
    });
}

std::string read_first_line(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    return line;
}

// Rebuilt from the directory listing by every failing test, so concurrent tests each leave a
// complete index (the rename is atomic; the last writer has seen every earlier label).
void write_index() {
    std::ostringstream html;
    html << "<!doctype html><meta charset=utf-8><title>sweeptrace image tests: failures</title>"
            "<h1>Failing image tests</h1><ul>";
    for (const auto& entry : std::filesystem::directory_iterator(output_root))
        if (std::filesystem::exists(entry.path() / "report.html")) {
            const std::string label = entry.path().filename().string();
            html << "<li><a href=\"" << label << "/report.html\">" << html_escape(label) << "</a>: "
                 << html_escape(read_first_line(entry.path() / "verdict.txt")) << "</li>";
        }
    html << "</ul>";
    write_text_atomically(output_root / "report.html", html.str());
}

}  // namespace

std::vector<GoldenSpec> read_golden_specs() {
    const std::filesystem::path table = source_dir / "reference_images" / "goldens.txt";
    std::ifstream in(table);
    if (!in) throw std::runtime_error("cannot read " + table.string());
    std::vector<GoldenSpec> specs;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        GoldenSpec s;
        if (!(fields >> s.scene >> s.width >> s.height >> s.max_depth >> s.golden_spp >> s.golden_seed >> s.test_spp >>
              s.block))
            throw std::runtime_error(table.string() + ":" + std::to_string(number) + ": expected 8 fields");
        specs.push_back(s);
    }
    return specs;
}

const GoldenSpec& golden_spec(const std::string& scene) {
    static const std::vector<GoldenSpec> specs = read_golden_specs();
    for (const auto& s : specs)
        if (s.scene == scene) return s;
    throw std::runtime_error("reference_images/goldens.txt has no line for " + scene);
}

std::filesystem::path golden_image_path(const GoldenSpec& spec) {
    return source_dir / "reference_images" / (spec.scene + ".png");
}

std::filesystem::path golden_variance_path(const GoldenSpec& spec) {
    return source_dir / "reference_images" / (spec.scene + "-variance.exr");
}

void make_golden(const GoldenSpec& spec) {
    const Scene scene = load_golden_scene(spec);
    const auto accel = make_accel(AccelKind::Bvh, scene);
    RenderOptions options;
    options.spp = spec.golden_spp;
    options.max_depth = spec.max_depth;
    options.seed = spec.golden_seed;
    options.integrator = scene.film.integrator;  // a scene's golden is its own method's image
    RenderResult r = render(scene, *accel, options);
    if (r.stats.nonfinite_samples != 0)
        throw std::runtime_error(spec.scene + ": " + std::to_string(r.stats.nonfinite_samples) + " non-finite samples");
    for (auto& p : r.variance.pixels) p *= static_cast<float>(spec.golden_spp);  // per sample
    write_image(r.image, golden_image_path(spec));  // PNG: clamped to [0, 1], sRGB, as `render -o x.png`
    write_image(r.variance, golden_variance_path(spec));
}

Scene load_golden_scene(const GoldenSpec& spec) {
    Scene scene = load_scene(source_dir / "scenes" / (spec.scene + ".json"));
    scene.film.width = spec.width;
    scene.film.height = spec.height;
    scene.film.max_depth = spec.max_depth;
    return scene;
}

RenderResult render_for_test(const Scene& scene, AccelKind accel, const GoldenSpec& spec, std::uint64_t seed,
                             PlantedDefect defect) {
    const auto structure = make_accel(accel, scene);
    RenderOptions options;
    options.spp = spec.test_spp;
    options.max_depth = spec.max_depth;
    options.seed = seed;
    options.integrator = scene.film.integrator;
    return render_with_planted_defect(scene, *structure, options, defect);
}

GoldenVerdict compare_to_golden(const GoldenSpec& spec, const RenderResult& result, const std::string& label,
                                bool expect_accept) {
    const std::filesystem::path golden_path = golden_image_path(spec);
    const Image golden = read_image(golden_path);
    BlockTestOptions options;
    options.block = spec.block;
    options.golden_is_8bit = true;
    options.reference_noise_ratio = static_cast<double>(spec.test_spp) / spec.golden_spp;
    // The golden's per-sample variance, scaled to the test's spp: what the render's pixel means
    // should scatter by if it is right (block_test takes the larger of this and its own).
    Image null_variance = read_image(golden_variance_path(spec));
    for (auto& p : null_variance.pixels) p /= static_cast<float>(spec.test_spp);
    options.null_variance = &null_variance;
    GoldenVerdict v;
    v.block = block_test(golden, result.image, result.variance, options);
    v.metrics = compare_images(result.image, golden);

    const std::filesystem::path dir = output_root / label;
    std::error_code ignored;
    std::filesystem::remove_all(dir, ignored);  // a stale report must not outlive a fixed test
    const char* keep = std::getenv("SWEEPTRACE_KEEP_IMAGES");
    const bool failing = v.accepted() != expect_accept;
    if (!failing && !(keep && std::string(keep) == "1")) {
        if (std::filesystem::exists(output_root)) write_index();
        return v;
    }
    std::filesystem::create_directories(dir);
    write_image(golden, dir / "golden.png");
    write_image(result.image, dir / "actual.png");
    write_image(result.image, dir / "actual.pfm");
    write_image(block_z_heatmap(v.block, golden.width, golden.height, spec.block), dir / "heatmap.png");
    write_image(difference_heatmap(result.image, golden, DiffOptions{}, 0.2), dir / "diff.png");
    const std::string expectation = expect_accept ? "expected: accepted" : "expected: rejected";
    const std::string verdict = std::string(v.accepted() ? "accepted" : "REJECTED") + " (" + expectation + "); " +
                                v.block.summary();
    write_text_atomically(dir / "verdict.txt", verdict + "\n");
    char metrics[300];
    std::snprintf(metrics, sizeof metrics,
                  "display-space RMSE %.5f, PSNR %.2f dB, max |diff| %.4f at (%d, %d), mean delta E %.3f",
                  v.metrics.rmse, v.metrics.psnr, v.metrics.max_abs, v.metrics.max_x, v.metrics.max_y,
                  v.metrics.mean_delta_e);
    std::ostringstream html;
    html << "<!doctype html><meta charset=utf-8><title>" << html_escape(label) << "</title>"
         << "<style>img{width:" << 3 * golden.width << "px;image-rendering:pixelated}td{padding:4px;"
         << "text-align:center;vertical-align:top}</style>"
         << "<h1>" << html_escape(label) << "</h1><p>" << html_escape(verdict) << "</p><p>" << html_escape(metrics)
         << "</p><p>scene " << html_escape(spec.scene) << ", " << spec.width << "x" << spec.height << ", "
         << spec.test_spp << " spp against a " << spec.golden_spp << " spp golden; " << spec.block << "x"
         << spec.block << " blocks</p><table><tr><th>golden</th><th>actual</th><th>block z (red = 2x limit)</th>"
         << "<th>|difference| (red = 0.2)</th></tr><tr><td><img src=golden.png></td><td><img src=actual.png></td>"
         << "<td><img src=heatmap.png></td><td><img src=diff.png></td></tr></table>";
    write_text_atomically(dir / "report.html", html.str());
    write_index();
    if (failing)
        std::printf("image test '%s' %s\n  golden:  %s\n  actual:  %s\n  heatmap: %s\n  report:  %s\n  index:   %s\n",
                    label.c_str(), verdict.c_str(), (dir / "golden.png").c_str(), (dir / "actual.png").c_str(),
                    (dir / "heatmap.png").c_str(), (dir / "report.html").c_str(), (output_root / "report.html").c_str());
    return v;
}

}  // namespace sweeptrace::testing
