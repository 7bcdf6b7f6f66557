// sweeptrace accuracy: every ray-shape routine, robust and thesis variants (and Embree for
// triangles), over the ray families of raytracer/accuracy/cases.hpp, scored against the long
// double reference. Prints the Markdown table; --csv / --markdown also save it.
// With --meshes DIR: the native BVH against Embree (default and robust) on real meshes instead.
// With --structures: the thesis's structures redone for rays, speed against triangle count.
// With --tessellation: the same objects analytic and tessellated, rendered.
// With --convergence SCENE...: image error against time, BSDF-only / NEE+MIS, BVH / Embree.
// With --sampling SCENE...: Sobol against independent samples, adaptive against classic roulette.
// With --motion: moving objects, the native BVH and Embree's motion blur against brute force.
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "raytracer/accuracy/exchange.hpp"
#include "raytracer/accuracy/legend.hpp"
#include "raytracer/accuracy/mesh_compare.hpp"
#include "raytracer/accuracy/motion_study.hpp"
#include "raytracer/accuracy/render_studies.hpp"
#include "raytracer/accuracy/report.hpp"
#include "raytracer/accuracy/routines.hpp"
#include "raytracer/accuracy/sampling_study.hpp"
#include "raytracer/accuracy/structures.hpp"
#include "raytracer/cli/commands.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace {

namespace {

struct AccuracyOptions {
    std::size_t rays = 20000;
    std::uint64_t seed = 1;
    std::string csv, markdown, methods_csv;
    std::string export_rays, score, variant_name = "results";  // exchange.hpp
    std::vector<std::string> shapes;
    std::string meshes;
    std::size_t inside_rays = 100000;
    bool structures = false;
    bool motion = false;
    int max_level = 8;
    double budget = 0.5;
    bool tessellation = false;
    std::vector<std::string> convergence;
    std::vector<std::string> sampling;
    int roulette_spp = 256;
    bool roulette_only = false;
    std::string cache = "sampling-cache";
    int size = 96, spp = 16, reference_spp = 256, max_exponent = 6;
};

void run(const AccuracyOptions& o) {
    for (const std::string* path : {&o.csv, &o.markdown, &o.methods_csv}) {
        if (!path->empty()) accuracy::check_writable(*path);
    }
    if (!o.methods_csv.empty() && o.meshes.empty()) throw InputError("--methods-csv: only with --meshes");
    if (int(o.structures) + int(!o.meshes.empty()) + int(o.tessellation) + int(!o.convergence.empty()) +
            int(!o.sampling.empty()) + int(o.motion) > 1) {
        throw InputError("--structures, --meshes, --tessellation, --convergence, --sampling and --motion: choose one");
    }
    if (o.motion) {
        const auto rows = accuracy::measure_motion(o.rays, o.seed);
        accuracy::write_motion_markdown(std::cout, rows);
        if (!o.csv.empty()) accuracy::save_file(o.csv, [&](std::ostream& f) { accuracy::write_motion_csv(f, rows); });
        if (!o.markdown.empty())
            accuracy::save_file(o.markdown, [&](std::ostream& f) { accuracy::write_motion_markdown(f, rows); });
        return;
    }
    if (!o.sampling.empty()) {
        std::vector<std::filesystem::path> scenes(o.sampling.begin(), o.sampling.end());
        const auto report = accuracy::sampling_study(scenes, o.size, o.reference_spp, o.roulette_spp, o.cache,
                                                     !o.roulette_only);
        accuracy::write_sampling_markdown(std::cout, report);
        if (!o.csv.empty()) accuracy::save_file(o.csv, [&](std::ostream& f) { accuracy::write_sampling_csv(f, report); });
        if (!o.markdown.empty()) {
            accuracy::save_file(o.markdown, [&](std::ostream& f) { accuracy::write_sampling_markdown(f, report); });
        }
        return;
    }
    if (o.tessellation) {
        const auto rows = accuracy::tessellation_study(o.size, o.spp, o.reference_spp, o.max_exponent, unsigned(o.seed));
        accuracy::write_tessellation_markdown(std::cout, rows);
        if (!o.csv.empty()) accuracy::save_file(o.csv, [&](std::ostream& f) { accuracy::write_tessellation_csv(f, rows); });
        if (!o.markdown.empty()) {
            accuracy::save_file(o.markdown, [&](std::ostream& f) { accuracy::write_tessellation_markdown(f, rows); });
        }
        return;
    }
    if (!o.convergence.empty()) {
        std::vector<std::filesystem::path> scenes(o.convergence.begin(), o.convergence.end());
        const auto rows = accuracy::convergence_study(scenes, o.size, o.spp, o.reference_spp);
        accuracy::write_convergence_markdown(std::cout, rows);
        if (!o.csv.empty()) accuracy::save_file(o.csv, [&](std::ostream& f) { accuracy::write_convergence_csv(f, rows); });
        if (!o.markdown.empty()) {
            accuracy::save_file(o.markdown, [&](std::ostream& f) { accuracy::write_convergence_markdown(f, rows); });
        }
        return;
    }
    if (o.structures) {
        if (!o.meshes.empty()) throw InputError("--structures and --meshes: choose one");
        const auto rows = accuracy::measure_structures(2, o.max_level, o.rays, o.budget, o.seed);
        accuracy::write_structures_markdown(std::cout, rows);
        if (!o.csv.empty()) accuracy::save_file(o.csv, [&](std::ostream& f) { accuracy::write_structures_csv(f, rows); });
        if (!o.markdown.empty()) {
            accuracy::save_file(o.markdown, [&](std::ostream& f) { accuracy::write_structures_markdown(f, rows); });
        }
        return;
    }
    if (!o.meshes.empty()) {
        const auto meshes = accuracy::load_accuracy_meshes(o.meshes);
        const accuracy::MeshReport report = accuracy::compare_meshes(meshes, o.rays, o.inside_rays, o.seed);
        accuracy::write_mesh_markdown(std::cout, report);
        if (!o.csv.empty()) {
            accuracy::save_file(o.csv, [&](std::ostream& f) { accuracy::write_comparisons_csv(f, report.comparisons); });
        }
        if (!o.methods_csv.empty()) {
            accuracy::save_file(o.methods_csv, [&](std::ostream& f) { accuracy::write_methods_csv(f, report.methods); });
        }
        if (!o.markdown.empty()) {
            accuracy::save_file(o.markdown, [&](std::ostream& f) { accuracy::write_mesh_markdown(f, report); });
        }
        return;
    }
    if (!o.export_rays.empty()) {
        accuracy::export_rays(o.export_rays, o.shapes, o.rays, o.seed);
        std::cout << "wrote the ray families to " << o.export_rays << " (manifest.json lists the files)\n";
        return;
    }
    std::vector<accuracy::PointErrors> points;
    const auto rows = o.score.empty() ? accuracy::run_routines(o.shapes, o.rays, o.seed)
                                      : accuracy::score_results(o.score, o.rays, o.seed, o.variant_name, &points);
    accuracy::write_markdown(std::cout, rows);
    accuracy::write_point_errors(std::cout, points);
    accuracy::write_legend(std::cout);
    if (!o.csv.empty()) accuracy::save_file(o.csv, [&](std::ostream& f) { accuracy::write_csv(f, rows); });
    if (!o.markdown.empty()) {
        accuracy::save_file(o.markdown, [&](std::ostream& f) {
            accuracy::write_markdown(f, rows);
            accuracy::write_legend(f);
        });
    }
}

}  // namespace

void add_accuracy_command(CLI::App& app, int& exit_code) {
    auto options = std::make_shared<AccuracyOptions>();
    auto* cmd = app.add_subcommand(
        "accuracy", "Measure every ray-shape intersector (robust, thesis, Embree) against a long double reference");
    cmd->add_option("--rays", options->rays, "Rays per family and routine (with --meshes: per mesh)")
        ->check(CLI::Range(1, 100000000));
    cmd->add_option("--seed", options->seed, "Seed of the ray families");
    cmd->add_option("--csv", options->csv, "Also write the table as CSV to this file");
    cmd->add_option("--markdown", options->markdown, "Also write the table(s) as Markdown to this file");
    cmd->add_option("--export-rays", options->export_rays,
                    "Write the primary-ray families (shapes, rays, reference verdict and t) as JSON lines into DIR "
                    "(docs/accuracy-for-your-intersector.md)");
    cmd->add_option("--score", options->score,
                    "Score a results file (JSON lines: case, hit, t) with the same table; use the --rays and --seed "
                    "of the export")
        ->check(CLI::ExistingFile);
    cmd->add_option("--variant-name", options->variant_name, "With --score: the variant column's name")
        ->capture_default_str();
    cmd->add_option("--shape", options->shapes, "Only these shapes (repeatable)")
        ->check(CLI::IsMember(accuracy::routine_shape_names()));
    cmd->add_option("--meshes", options->meshes,
                    "Compare the native BVH with Embree on the meshes in this directory (../shared/meshes) instead");
    cmd->add_option("--inside-rays", options->inside_rays, "With --meshes: rays from inside each closed mesh")
        ->check(CLI::Range(0, 100000000));
    cmd->add_option("--methods-csv", options->methods_csv,
                    "With --meshes: write per-method speed, build time and leaks as CSV to this file");
    cmd->add_flag("--motion", options->motion,
                  "Moving objects: native BVH and Embree motion blur against brute force on random (ray, time) pairs");
    cmd->add_flag("--structures", options->structures,
                  "Brute force, 8 octants, hashed grid, BVH and Embree on icospheres of 320 .. 1.3M triangles");
    cmd->add_option("--max-level", options->max_level, "With --structures: finest icosphere level (8 = 1.3M triangles)")
        ->check(CLI::Range(2, 9));
    cmd->add_option("--budget", options->budget, "With --structures: seconds of tracing per structure and size")
        ->check(CLI::Range(0.001, 600.0));
    cmd->add_flag("--tessellation", options->tessellation,
                  "Render sphere, cylinder, capsule, ellipsoid analytic and tessellated (1e2 .. 10^max-exponent triangles)");
    cmd->add_option("--max-exponent", options->max_exponent, "With --tessellation: up to 10^this triangles")
        ->check(CLI::Range(2, 7));
    cmd->add_option("--convergence", options->convergence, "Image error against time for these scene files")
        ->check(CLI::ExistingFile);
    cmd->add_option("--sampling", options->sampling,
                    "Sobol against independent samples and adaptive against classic roulette, RMSE at 16-1024 spp "
                    "and at equal CPU time, for these scene files")
        ->check(CLI::ExistingFile);
    cmd->add_option("--roulette-spp", options->roulette_spp,
                    "With --sampling: samples per pixel of the roulette candidates' variance x time (0: skip)")
        ->check(CLI::Range(0, 1 << 16));
    cmd->add_flag("--roulette-only", options->roulette_only, "With --sampling: only the roulette candidates");
    cmd->add_option("--cache", options->cache,
                    "With --sampling: directory for the cached reference renders (run from the build tree)")
        ->capture_default_str();
    cmd->add_option("--size", options->size, "With --tessellation / --convergence / --sampling: image width in pixels")
        ->check(CLI::Range(8, 4096));
    cmd->add_option("--spp", options->spp,
                    "With --tessellation: samples per pixel; with --convergence: the largest of 1, 2, 4 ...")
        ->check(CLI::Range(1, 1 << 16));
    cmd->add_option("--reference-spp", options->reference_spp, "Samples per pixel of the converged reference render")
        ->check(CLI::Range(1, 1 << 20));
    cmd->callback([options, &exit_code] {
        run(*options);
        exit_code = 0;
    });
}

}  // namespace sweeptrace
