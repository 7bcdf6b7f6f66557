// sweeptrace accuracy: every ray-shape routine, robust and thesis variants (and Embree for
// triangles), over the ray families of raytracer/accuracy/cases.hpp, scored against the long
// double reference. Prints the Markdown table; --csv / --markdown also save it.
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "raytracer/accuracy/report.hpp"
#include "raytracer/accuracy/routines.hpp"
#include "raytracer/cli/commands.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace {

namespace {

struct AccuracyOptions {
    std::size_t rays = 20000;
    std::uint64_t seed = 1;
    std::string csv, markdown;
    std::vector<std::string> shapes;
};

}  // namespace

void add_accuracy_command(CLI::App& app, int& exit_code) {
    auto options = std::make_shared<AccuracyOptions>();
    auto* cmd = app.add_subcommand(
        "accuracy", "Measure every ray-shape intersector (robust, thesis, Embree) against a long double reference");
    cmd->add_option("--rays", options->rays, "Rays per family and routine")->check(CLI::Range(1, 100000000));
    cmd->add_option("--seed", options->seed, "Seed of the ray families");
    cmd->add_option("--csv", options->csv, "Also write the table as CSV to this file");
    cmd->add_option("--markdown", options->markdown, "Also write the table as Markdown to this file");
    cmd->add_option("--shape", options->shapes, "Only these shapes (repeatable)")
        ->check(CLI::IsMember(accuracy::routine_shape_names()));
    cmd->callback([options, &exit_code] {
        const auto rows = accuracy::run_routines(options->shapes, options->rays, options->seed);
        accuracy::write_markdown(std::cout, rows);
        if (!options->csv.empty()) accuracy::save_table(options->csv, rows, false);
        if (!options->markdown.empty()) accuracy::save_table(options->markdown, rows, true);
        exit_code = 0;
    });
}

}  // namespace sweeptrace
