// `sweeptrace reference-check FOLDER [--scene NAME]... [--downsample F | --width W] [--spp N]
// [--table FILE.md] [--pictures DIR]`: every scene of FOLDER (a subfolder holding a pbrt-v4 scene
// and the reference image another renderer made of it, as ../shared/bitterli has them) rendered
// through the importer and judged against the reference: image mean ratio per channel, the share
// of 8x8 blocks within |z| < 3 and < 5 (our variance plus the reference's own noise), the median
// signed block error, and a picture ours | reference | z map (image/reference_compare.hpp holds
// the numbers). Stand-in textures (scene/stand_in_mask.hpp) and non-finite reference pixels are
// masked. Everything is read and checked before the first render, so bad input writes nothing.
// Exit 0 when every scene matches (each channel's mean within 1 %, at least 97 % of blocks within
// |z| < 3), 1 when one does not, 2 on bad input.
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "raytracer/accel/accel.hpp"
#include "raytracer/cli/commands.hpp"
#include "raytracer/cli/memory_budget.hpp"
#include "raytracer/cli/output_guard.hpp"
#include "raytracer/cli/program_version.hpp"
#include "raytracer/cli/report_text.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/image/reference_compare.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/render/renderer.hpp"
#include "raytracer/scene/pbrt/pbrt_import.hpp"
#include "raytracer/scene/text_file.hpp"
#include "raytracer/scene/stand_in_mask.hpp"

namespace sweeptrace {
namespace {

namespace fs = std::filesystem;

// The generated part of the table file: a hand-written page around it keeps its own text.
constexpr const char* kTableBegin = "<!-- reference-check: begin (generated, do not edit) -->";
constexpr const char* kTableEnd = "<!-- reference-check: end -->";

struct ReferenceCheckArgs {
    std::string folder;
    std::vector<std::string> scenes;  // empty: every subfolder with both files
    std::string scene_file = "scene-v4.pbrt";
    std::string reference_file = "TungstenRender.exr";
    int downsample = 4;
    int width = 0;  // > 0: the downsample factor is the reference's width / this
    int spp = 1024;
    // Independent sample ranges, for the block variance of splatting integrators; 0: the largest
    // K <= 16 that divides spp with at least 2 samples per batch.
    int batches = 0;
    int mask_spp = 16;
    std::vector<std::string> max_depths;  // "N" for every scene or "NAME=N" for one; default the scene's
    std::vector<std::string> integrators;  // "KIND" for every scene or "NAME=KIND" for one; default the scene's
    int threads = 0;
    std::uint64_t seed = 1;
    std::string filter = "box";
    std::vector<std::string> stand_ins;
    std::string table;
    std::string pictures;
    CLI::Option* downsample_opt = nullptr;
};

struct SceneInput {
    std::string name;
    fs::path scene, reference;
    int factor = 1;
    int max_depth = 0;  // 0: the scene's
    std::optional<IntegratorKind> integrator;  // none: the scene's
    std::vector<NamedFile> reads;  // every file its check reads: the scene and its inputs, the reference
};

struct SceneRow {
    std::string name;
    int width = 0, height = 0;
    BlockComparison blocks;
    // The replicas' block variance over the pixel-variance sum (block_variance_scale); applied to
    // our variance when the integrator splats (bdpt, vcm), as measured, and reported for every scene.
    // It can be below 1: one light vertex's splat lands on one pixel of a block or another, never
    // both, which correlates those pixels negatively (one subpath's several vertices landing near
    // each other correlate them positively).
    double variance_scale = 1.0;
    bool scale_applied = false;
    std::vector<std::string> warnings, stand_ins;
    double cpu_seconds = 0.0, wall_seconds = 0.0;
    std::string picture;  // relative to the table's folder
    bool matches() const {
        const glm::dvec3& m = blocks.mean_ratio;
        return std::abs(m.x - 1.0) <= 0.01 && std::abs(m.y - 1.0) <= 0.01 && std::abs(m.z - 1.0) <= 0.01 &&
               blocks.share_within_3 >= 0.97;
    }
};

double process_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}


// --max-depth "N" (every scene) or "NAME=N" (that scene; it wins over "N"): 0 when none applies.
int depth_for(const std::vector<std::string>& settings, const std::string& scene) {
    int all = 0, mine = 0;
    for (const std::string& d : settings) {
        const std::size_t eq = d.find('=');
        const std::string number = eq == std::string::npos ? d : d.substr(eq + 1);
        char* end = nullptr;
        const long v = std::strtol(number.c_str(), &end, 10);
        if (number.empty() || *end != '\0' || v < 1 || v > 1024)
            throw InputError("reference-check: --max-depth '" + d + "': give N or NAME=N with N in 1..1024 (path vertices after the camera)");
        if (eq == std::string::npos) all = int(v);
        else if (d.substr(0, eq) == scene) mine = int(v);
    }
    return mine > 0 ? mine : all;
}

// The --integrator settings for `scene`: NAME=KIND for it, else KIND for every scene, else none
// (the scene file's own).
std::optional<IntegratorKind> integrator_for(const std::vector<std::string>& settings, const std::string& scene) {
    std::optional<IntegratorKind> all, mine;
    for (const std::string& d : settings) {
        const std::size_t eq = d.find('=');
        const std::string kind = eq == std::string::npos ? d : d.substr(eq + 1);
        const std::optional<IntegratorKind> k = kind == "path"   ? std::optional(IntegratorKind::Path)
                                                : kind == "bdpt" ? std::optional(IntegratorKind::Bdpt)
                                                : kind == "vcm"  ? std::optional(IntegratorKind::Vcm)
                                                                 : std::nullopt;
        if (!k) throw InputError("reference-check: --integrator '" + d + "': give KIND or NAME=KIND with KIND path, bdpt or vcm");
        if (eq == std::string::npos) all = k;
        else if (d.substr(0, eq) == scene) mine = k;
    }
    return mine ? mine : all;
}

// --stand-in files, relative to the folder unless absolute.
std::vector<fs::path> stand_in_paths(const ReferenceCheckArgs& a) {
    std::vector<fs::path> named;
    for (const std::string& s : a.stand_ins) named.push_back(fs::path(s).is_absolute() ? fs::path(s) : fs::path(a.folder) / s);
    return named;
}

// A --scene name is a subfolder's name: "../elsewhere" or "a/b" would check a folder outside the
// one given (and print and write under a name that is not a subfolder's).
void require_subfolder_name(const std::string& n) {
    if (n.empty() || n == "." || n == ".." || n.find('/') != std::string::npos)
        throw InputError("reference-check: --scene '" + n + "': give the name of a subfolder of the folder, not a path");
}

// A reference another renderer made holds radiance: no negative value, and at least one pixel
// of the downsampled reference made of finite source pixels only (the others are masked, and
// with none left every mean ratio would be 0 / 0). Allocates nothing: it runs before the memory
// estimate is known to fit.
void check_reference(const SceneInput& s, const Image& ref) {
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x) {
            const glm::vec3& p = ref.at(x, y);
            if (p.x < 0.0f || p.y < 0.0f || p.z < 0.0f)
                throw InputError("reference-check: scene '" + s.name + "': reference '" + s.reference.string() +
                                 "': pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                 ") is negative; a reference holds radiance, never below 0");
        }
    const auto finite = [](const glm::vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); };
    const int f = s.factor;
    for (int y = 0; y + f <= ref.height; y += f)
        for (int x = 0; x + f <= ref.width; x += f) {
            bool all = true;
            for (int sy = y; sy < y + f && all; ++sy)
                for (int sx = x; sx < x + f && all; ++sx) all = finite(ref.at(sx, sy));
            if (all) return;
        }
    throw InputError("reference-check: scene '" + s.name + "': reference '" + s.reference.string() +
                     "': no pixel at the render's size is made of finite source pixels (NaN and infinite ones are "
                     "masked), so nothing could be compared");
}

// The memory of one scene's check, before anything is rendered: the render's own estimate (twice
// with a stand-in mask, rendered while the image is kept) plus, per pixel, the batch images (K
// vec3), their mean and variance (2 dvec3 and 2 vec3), the downsampled reference with its variance
// and mask, and the comparison picture (three panels, float and 8-bit); per reference pixel, the
// reference and its noise estimate (2 vec3).
void check_refcheck_memory(const SceneInput& s, Scene scene, int ref_w, int ref_h, const ReferenceCheckArgs& a) {
    scene.film.width = ref_w / s.factor;
    scene.film.height = ref_h / s.factor;
    if (s.max_depth > 0) scene.film.max_depth = s.max_depth;
    if (s.integrator) scene.film.integrator = *s.integrator;
    const MemoryEstimate e = estimate_render_memory(scene);
    const std::uint64_t px = std::uint64_t(scene.film.width) * std::uint64_t(scene.film.height);
    const std::uint64_t per_px = std::uint64_t(a.batches) * 12 + 2 * 24 + 2 * 12 + 2 * 12 + 1 + 3 * (12 + 3);
    const std::uint64_t total = e.total() + e.film + px * per_px + std::uint64_t(ref_w) * std::uint64_t(ref_h) * 24;
    check_memory_estimate(total, std::nullopt, "reference-check: scene '" + s.name + "'",
                          std::to_string(scene.film.width) + "x" + std::to_string(scene.film.height) + " from a " +
                              std::to_string(ref_w) + "x" + std::to_string(ref_h) + " reference, " +
                              std::to_string(a.batches) + " batches");
}

// The scenes to check, each with its reference's downsample factor; everything a run needs is
// checked here, before anything is rendered or written.
std::vector<SceneInput> refcheck_inputs(const ReferenceCheckArgs& a) {
    std::error_code ec;
    const fs::path folder(a.folder);
    if (!fs::is_directory(folder, ec)) throw InputError("reference-check: folder '" + a.folder + "' does not exist");
    std::vector<std::string> names = a.scenes;
    for (const std::string& n : names) require_subfolder_name(n);
    if (names.empty()) {
        for (const auto& e : fs::directory_iterator(folder))
            if (e.is_directory() && fs::exists(e.path() / a.scene_file) && fs::exists(e.path() / a.reference_file))
                names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        if (names.empty())
            throw InputError("reference-check: no subfolder of '" + a.folder + "' holds both " + a.scene_file + " and " +
                             a.reference_file);
    }
    for (const std::string& d : a.max_depths)
        if (const std::size_t eq = d.find('='); eq != std::string::npos &&
                                                std::find(names.begin(), names.end(), d.substr(0, eq)) == names.end())
            throw InputError("reference-check: --max-depth '" + d + "': no scene '" + d.substr(0, eq) + "' is checked");
    for (const std::string& d : a.integrators)
        if (const std::size_t eq = d.find('='); eq != std::string::npos &&
                                                std::find(names.begin(), names.end(), d.substr(0, eq)) == names.end())
            throw InputError("reference-check: --integrator '" + d + "': no scene '" + d.substr(0, eq) + "' is checked");
    for (const fs::path& p : stand_in_paths(a))
        if (const std::string problem = file_kind_problem(p); !problem.empty())
            throw InputError("reference-check: --stand-in '" + p.string() + "' " + problem);
    std::vector<SceneInput> out;
    for (const std::string& n : names) {
        SceneInput s;
        s.name = n;
        s.scene = folder / n / a.scene_file;
        s.reference = folder / n / a.reference_file;
        for (const fs::path& p : {s.scene, s.reference})
            if (const std::string problem = file_kind_problem(p); !problem.empty())
                throw InputError("reference-check: scene '" + n + "': '" + p.string() + "' " + problem);
        const Image ref = read_image(s.reference);
        s.factor = a.width > 0 ? ref.width / a.width : a.downsample;
        if (s.factor < 1 || ref.width % s.factor != 0 || ref.height % s.factor != 0)
            throw InputError("reference-check: scene '" + n + "': the reference is " + std::to_string(ref.width) + "x" +
                             std::to_string(ref.height) + ", which " +
                             (a.width > 0 ? "--width " + std::to_string(a.width) : "--downsample " + std::to_string(a.downsample)) +
                             " does not divide into whole pixels (the box filter averages whole source pixels)");
        s.max_depth = depth_for(a.max_depths, n);
        s.integrator = integrator_for(a.integrators, n);
        std::vector<std::string> warnings;
        const Scene scene = load_pbrt_scene(s.scene, false, warnings);  // a scene that cannot be read fails now, not after hours
        check_refcheck_memory(s, scene, ref.width, ref.height, a);
        check_reference(s, ref);
        s.reads = {{"scene", s.scene}, {"reference", s.reference}};
        for (const fs::path& f : scene.input_files) s.reads.push_back({"scene's input", f});
        out.push_back(s);
    }
    return out;
}

void refcheck_require_folder(const std::string& path, const char* what) {
    std::error_code ec;
    const fs::path parent = fs::absolute(path).parent_path();
    if (!fs::is_directory(parent, ec))
        throw InputError(std::string("reference-check: ") + what + " '" + path + "': directory '" + parent.string() +
                         "' does not exist");
}

RenderResult refcheck_render(const Scene& scene, int spp, int max_depth, const ReferenceCheckArgs& a,
                             const Accel* shared_accel = nullptr, int first_sample = 0) {
    std::unique_ptr<Accel> own;
    if (!shared_accel) own = make_accel(AccelKind::Bvh, scene);
    const Accel& accel = shared_accel ? *shared_accel : *own;
    RenderOptions o;
    o.spp = spp;
    o.first_sample = first_sample;
    o.max_depth = max_depth;
    o.threads = a.threads;
    o.seed = a.seed;
    // Independent samples: the render's variance estimate is then exact (under Sobol it overstates
    // the variance, and the z-test would be too lenient).
    o.sampler = SamplerKind::Independent;
    o.guiding = false;
    o.integrator = scene.film.integrator;  // pbrt's Integrator "bdpt" and "sppm" render with ours (bdpt, vcm)
    return render(scene, accel, o);
}

// Our render as `batches` disjoint sample ranges of the one render (the same samples as a single
// render of `spp`): their mean and its per-pixel variance, and each batch's image for the
// replicas' block variance. A bidirectional render's splats correlate neighbouring pixels, so the
// sum of pixel variances understates a block's; independent batches measure it.
struct BatchedRender {
    Image image, variance;
    std::vector<Image> batches;
};

BatchedRender refcheck_batched(const Scene& scene, int max_depth, const ReferenceCheckArgs& a) {
    const std::unique_ptr<Accel> accel = make_accel(AccelKind::Bvh, scene);
    const int k = a.batches, per = a.spp / a.batches;
    BatchedRender out;
    const int w = scene.film.width, h = scene.film.height;
    std::vector<glm::dvec3> mean(static_cast<std::size_t>(w) * h), var(mean.size());
    for (int b = 0; b < k; ++b) {
        RenderResult r = refcheck_render(scene, per, max_depth, a, accel.get(), b * per);
        for (std::size_t i = 0; i < mean.size(); ++i) {
            mean[i] += glm::dvec3(r.image.pixels[i]) / double(k);
            var[i] += glm::dvec3(r.variance.pixels[i]) / double(k) / double(k);
        }
        out.batches.push_back(std::move(r.image));
    }
    out.image = Image(w, h);
    out.variance = Image(w, h);
    for (std::size_t i = 0; i < mean.size(); ++i) {
        out.image.pixels[i] = glm::vec3(mean[i]);
        out.variance.pixels[i] = glm::vec3(var[i]);
    }
    return out;
}

SceneRow check_scene(const SceneInput& in, const ReferenceCheckArgs& a, const fs::path& picture_dir,
                     const fs::path& table_dir) {
    const double cpu0 = process_cpu_seconds();
    const auto wall0 = std::chrono::steady_clock::now();
    SceneRow row;
    row.name = in.name;
    const DownsampledReference ref = downsample_reference(read_image(in.reference), in.factor);
    Scene scene = load_pbrt_scene(in.scene, false, row.warnings);
    row.width = scene.film.width = ref.image.width;
    row.height = scene.film.height = ref.image.height;
    // A box pixel filter: our pixel is then the image integrated over the footprint that the box
    // downsampling averages the reference over (the reference's own filter, 1/factor of our
    // pixel, blurs little next to it).
    if (a.filter == "box") scene.film.filter = FilterSpec{};
    if (in.integrator) scene.film.integrator = *in.integrator;
    const int depth = in.max_depth > 0 ? in.max_depth : scene.film.max_depth;
    const BatchedRender ours = refcheck_batched(scene, depth, a);

    std::vector<std::uint8_t> valid = ref.valid;
    const std::vector<int> stand_ins = stand_in_textures(scene, stand_in_paths(a), true);
    for (const int t : stand_ins) row.stand_ins.push_back(fs::relative(scene.textures[t].image_file, fs::path(a.folder)).string());
    bool found = false;
    const Scene mask_scene = stand_in_mask_scene(scene, stand_ins, found);
    if (found) {
        // A pixel is left out when more than 2 % of its paths end on a stand-in.
        const RenderResult mask = refcheck_render(mask_scene, a.mask_spp, depth, a);
        for (std::size_t i = 0; i < valid.size(); ++i) {
            const glm::vec3& m = mask.image.pixels[i];
            if (std::max({m.x, m.y, m.z}) > 0.02f) valid[i] = 0;
        }
    }
    row.variance_scale = block_variance_scale(ours.batches, ours.variance, valid);
    row.scale_applied = scene.film.integrator != IntegratorKind::Path && a.batches >= 2;
    row.blocks = compare_blocks(ours.image, ours.variance, ref.image, ref.variance, valid, 8,
                                row.scale_applied ? row.variance_scale : 1.0);
    if (!picture_dir.empty()) {
        const fs::path pic = picture_dir / (in.name + ".png");
        write_image(comparison_picture(ours.image, ref.image, valid, row.blocks), pic);
        row.picture = fs::relative(fs::absolute(pic), fs::absolute(table_dir)).generic_string();
    }
    row.cpu_seconds = process_cpu_seconds() - cpu0;
    row.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    return row;
}

std::string share_text(double share) {
    char t[32];
    std::snprintf(t, sizeof t, "%.1f %%", 100.0 * share);
    return t;
}

std::string row_text(const SceneRow& r, int spp) {
    char t[600];
    const glm::dvec3& m = r.blocks.mean_ratio;
    std::snprintf(t, sizeof t, "| %s | %dx%d | %d | %.4f %.4f %.4f | %s | %s | %+.2f %% | %.2f%s | %s | %zu | %.0f (%.0f) | %s |",
                  escape_control(r.name).c_str(), r.width, r.height, spp, m.x, m.y, m.z, share_text(r.blocks.share_within_3).c_str(),
                  share_text(r.blocks.share_within_5).c_str(), 100.0 * r.blocks.median_relative_error, r.variance_scale,
                  r.scale_applied ? " (applied)" : "", share_text(1.0 - r.blocks.valid_share).c_str(), r.warnings.size(),
                  r.cpu_seconds, r.wall_seconds, r.matches() ? "yes" : "**no**");
    std::string s = t;
    if (!r.picture.empty()) s += " [picture](" + r.picture + ") |";
    return s;
}

// The command that reproduces the run, every setting spelled out.
std::string command_line(const ReferenceCheckArgs& a) {
    std::string c = "sweeptrace reference-check " + a.folder;
    for (const std::string& s : a.scenes) c += " --scene " + s;
    c += a.width > 0 ? " --width " + std::to_string(a.width) : " --downsample " + std::to_string(a.downsample);
    c += " --spp " + std::to_string(a.spp) + " --batches " + std::to_string(a.batches) + " --mask-spp " + std::to_string(a.mask_spp) + " --seed " + std::to_string(a.seed);
    for (const std::string& d : a.max_depths) c += " --max-depth " + d;
    for (const std::string& d : a.integrators) c += " --integrator " + d;
    if (a.filter != "box") c += " --filter " + a.filter;
    for (const std::string& s : a.stand_ins) c += " --stand-in " + s;
    if (!a.table.empty()) c += " --table " + a.table;
    if (!a.pictures.empty()) c += " --pictures " + a.pictures;
    return c;
}

std::string table_block(const std::vector<SceneRow>& rows, const ReferenceCheckArgs& a, double cores) {
    char date[64];
    const std::time_t now = std::time(nullptr);
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    std::string t = std::string(kTableBegin) + "\n";
    t += "Generated " + std::string(date) + " by sweeptrace " + program_version() + " (" + std::to_string(int(cores)) +
         " threads):\n\n```\n" + command_line(a) + "\n```\n\n";
    t += "| scene | size | spp | mean ratio R G B | blocks \\|z\\| < 3 | \\|z\\| < 5 | median block error | "
         "block variance / pixel sum | masked | importer warnings | CPU s (wall s) | matches | |\n";
    t += "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const SceneRow& r : rows) t += row_text(r, a.spp) + "\n";
    t += "\nStand-ins masked and the importer's warnings, per scene:\n\n";
    for (const SceneRow& r : rows) {
        t += "- **" + escape_control(r.name) + "**: ";
        if (r.stand_ins.empty()) t += "no stand-in";
        for (std::size_t i = 0; i < r.stand_ins.size(); ++i) t += (i ? ", `" : "stand-in `") + r.stand_ins[i] + "`";
        for (const std::string& w : r.warnings) {
            // The warning without the machine's path to the scene folder.
            const std::string prefix = fs::path(a.folder).string();
            const std::size_t at = w.find(prefix);
            t += "; `" + (at == 0 ? w.substr(prefix.size() + (w.size() > prefix.size() && w[prefix.size()] == '/')) : w) + "`";
        }
        t += "\n";
    }
    for (const SceneRow& r : rows)
        if (!r.picture.empty()) t += "\n![" + escape_control(r.name) + ": ours | reference | z map](" + r.picture + ")\n";
    t += std::string(kTableEnd) + "\n";
    return t;
}

// The table file as it will be written: a new page, or an existing one with its generated block
// replaced. A page without the markers is refused: it would lose hand-written text.
std::string table_file_text(const std::string& path, const std::string& block) {
    std::error_code ec;
    if (!fs::exists(path, ec)) return "# Reference scenes\n\n" + block;
    const std::string old = read_text_file(path, "the --table page");
    const std::size_t b = old.find(kTableBegin), e = old.find(kTableEnd);
    if (b == std::string::npos || e == std::string::npos || e < b)
        throw InputError("reference-check: --table '" + path + "' exists without the lines '" + kTableBegin + "' and '" +
                         kTableEnd + "' around its generated part; refusing to overwrite it");
    std::size_t after = e + std::string(kTableEnd).size();
    if (after < old.size() && old[after] == '\n') ++after;
    return old.substr(0, b) + block + old.substr(after);
}

int run_reference_check(ReferenceCheckArgs a) {
    if (a.width > 0 && a.downsample_opt->count())
        throw InputError("reference-check: give --width or --downsample, not both");
    if (a.filter != "box" && a.filter != "scene") throw InputError("reference-check: --filter is box or scene, got '" + a.filter + "'");
    if (a.batches == 0)
        for (int k = 16; k >= 1 && a.batches == 0; --k)
            if (a.spp % k == 0 && (a.spp / k >= 2 || k == 1)) a.batches = k;
    if (a.spp % a.batches != 0 || a.spp / a.batches < 2)
        throw InputError("reference-check: --spp " + std::to_string(a.spp) + " is not a multiple of --batches " +
                         std::to_string(a.batches) + " with at least 2 samples per batch (the batches split the "
                         "render's samples equally, and each needs its own variance)");
    if (!a.table.empty()) {
        if (fs::path(a.table).extension() != ".md") throw InputError("reference-check: --table '" + a.table + "': write a .md file");
        check_outputs({{"reference-check: --table", a.table}});  // a folder, FIFO or device is not read below
        table_file_text(a.table, "");  // refused now if it would lose text
    }
    fs::path pictures = a.pictures;
    if (pictures.empty() && !a.table.empty()) pictures = fs::path(a.table).replace_extension();
    std::error_code ec;
    if (!pictures.empty()) {
        refcheck_require_folder(pictures.string(), "--pictures");
        if (fs::exists(pictures, ec) && !fs::is_directory(pictures, ec))
            throw InputError("reference-check: --pictures '" + pictures.string() + "' " + file_kind_problem(pictures) +
                             ": the pictures go into a folder");
    }
    const std::vector<SceneInput> inputs = refcheck_inputs(a);
    // The one output rule (output_guard.hpp) over the table and every picture, against every file
    // any scene's check reads: a picture named like a reference, or a table that is a scene or one
    // of its Includes, is refused before the first render. A new pictures folder holds no input.
    std::vector<NamedFile> outputs{{"reference-check: --table", a.table}}, reads;
    for (const SceneInput& in : inputs) {
        if (!pictures.empty() && fs::is_directory(pictures, ec)) outputs.push_back({"reference-check: picture", pictures / (in.name + ".png")});
        reads.insert(reads.end(), in.reads.begin(), in.reads.end());
    }
    check_outputs(outputs, reads);
    if (!pictures.empty()) fs::create_directories(pictures);

    const fs::path table_dir = a.table.empty() ? fs::current_path() : fs::absolute(a.table).parent_path();
    std::vector<SceneRow> rows;
    bool all_match = true;
    for (const SceneInput& in : inputs) {
        rows.push_back(check_scene(in, a, pictures, table_dir));
        const SceneRow& r = rows.back();
        const glm::dvec3& m = r.blocks.mean_ratio;
        std::printf("%s %dx%d %d spp: mean ratio %.4f %.4f %.4f, blocks |z|<3 %s |z|<5 %s (%zu tested), median block "
                    "error %+.2f %%, block variance %.2f x the pixel sum%s, masked %s, %zu importer warnings, %.1f s CPU "
                    "%.1f s wall: %s\n",
                    escape_control(r.name).c_str(), r.width, r.height, a.spp, m.x, m.y, m.z, share_text(r.blocks.share_within_3).c_str(),
                    share_text(r.blocks.share_within_5).c_str(), r.blocks.tested, 100.0 * r.blocks.median_relative_error,
                    r.variance_scale, r.scale_applied ? " (applied)" : "",
                    share_text(1.0 - r.blocks.valid_share).c_str(), r.warnings.size(), r.cpu_seconds, r.wall_seconds,
                    r.matches() ? "matches" : "DOES NOT MATCH");
        std::fflush(stdout);
        all_match = all_match && r.matches();
    }
    if (!a.table.empty()) {
        const double threads = a.threads > 0 ? a.threads : double(std::max(1u, std::thread::hardware_concurrency()));
        write_text_file(a.table, table_file_text(a.table, table_block(rows, a, threads)));
    }
    return all_match ? 0 : 1;
}

}  // namespace

void add_reference_check_command(CLI::App& app, int& exit_code) {
    auto args = std::make_shared<ReferenceCheckArgs>();
    auto* cmd = app.add_subcommand(
        "reference-check",
        "Render every scene of a folder (subfolders with a pbrt-v4 scene and a reference image) and judge it against the "
        "reference: mean ratio per channel, share of 8x8 blocks within |z| < 3 and < 5, median block error, a picture "
        "ours | reference | z map; stand-in textures and non-finite reference pixels masked (docs/reference-scenes.md). "
        "Exit 0 when every scene matches (mean within 1 % per channel, >= 97 % of blocks within |z| < 3), 1 otherwise");
    cmd->add_option("folder", args->folder, "Folder of scenes, e.g. ../shared/bitterli")->required();
    cmd->add_option("--scene", args->scenes, "Only this subfolder (repeatable; default: every one with both files)");
    cmd->add_option("--scene-file", args->scene_file, "The scene's file name in each subfolder")->capture_default_str();
    cmd->add_option("--reference", args->reference_file, "The reference image's file name in each subfolder")->capture_default_str();
    args->downsample_opt = cmd->add_option("--downsample", args->downsample,
                                           "Render at the reference's size / F; the reference is box-filtered over whole "
                                           "F x F source pixels, so F must divide both sides")
                               ->capture_default_str()->check(CLI::Range(1, 64));
    cmd->add_option("--width", args->width, "Render this wide instead (the factor is the reference's width / W)")
        ->check(CLI::Range(8, 16384));
    cmd->add_option("--spp", args->spp, "Samples per pixel (independent sampler: exact variance)")->capture_default_str()
        ->check(CLI::Range(2, 1 << 20));
    cmd->add_option("--batches", args->batches,
                    "Split the render's samples into K equal independent batches; their spread measures each "
                    "block's variance, which splatting integrators (bdpt) correlate across pixels (1: off; default: "
                    "the largest K <= 16 dividing --spp with 2 samples per batch)")
        ->check(CLI::Range(1, 1024));
    cmd->add_option("--mask-spp", args->mask_spp, "Samples per pixel of the stand-in mask")->capture_default_str()
        ->check(CLI::Range(1, 4096));
    cmd->add_option("--max-depth", args->max_depths,
                    "Path vertices after the camera, N for every scene or NAME=N for one (repeatable; default: the "
                    "scene's), e.g. to render with the depth the reference was rendered with");
    cmd->add_option("--integrator", args->integrators,
                    "path, bdpt or vcm, KIND for every scene or NAME=KIND for one (repeatable; default: the scene's), "
                    "e.g. the method that converges in the check's time where the scene file names another");
    cmd->add_option("--threads", args->threads, "Worker threads, 0 = all cores")->capture_default_str()->check(CLI::Range(0, 1024));
    cmd->add_option("--seed", args->seed, "Random seed")->capture_default_str();
    cmd->add_option("--filter", args->filter, "Pixel filter of our render: box (matches the box downsampling) or scene")
        ->capture_default_str();
    cmd->add_option("--stand-in", args->stand_ins,
                    "A texture file (relative to the folder) that stands in for a missing one: the surfaces reading it are "
                    "masked (repeatable; flat textures of at most 8x8 texels are found without it)");
    cmd->add_option("--table", args->table, "Write the markdown table here (an existing page keeps its text outside the "
                                            "generated block)");
    cmd->add_option("--pictures", args->pictures, "Folder for the pictures (default: the table's path without .md)");
    cmd->callback([args, &exit_code] { exit_code = run_reference_check(*args); });
}

}  // namespace sweeptrace
