// sweeptrace: render | diff | accuracy | bench | noise-bench | merge | convert | reference-check | denoise. Bad input exits 2 with one message on stderr.
#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>

#include "raytracer/cli/commands.hpp"
#include "raytracer/input_error.hpp"

int main(int argc, char** argv) {
    CLI::App app{"sweeptrace: a path tracer on swept-segment collision tests"};
    app.require_subcommand(1);
    int exit_code = 0;
    sweeptrace::add_render_command(app, exit_code);
    sweeptrace::add_diff_command(app, exit_code);
    sweeptrace::add_accuracy_command(app, exit_code);
    sweeptrace::add_bench_command(app, exit_code);
    sweeptrace::add_noise_bench_command(app, exit_code);
    sweeptrace::add_merge_command(app, exit_code);
    sweeptrace::add_convert_command(app, exit_code);
    sweeptrace::add_reference_check_command(app, exit_code);
    sweeptrace::add_denoise_command(app, exit_code);
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {  // --help
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        // CLI11's own message, as one line with the program's prefix (it prints two, unprefixed).
        std::fprintf(stderr, "sweeptrace: error: %s (see --help)\n", sweeptrace::InputError(e.what()).what());
        return 2;
    } catch (const sweeptrace::InputError& e) {
        std::fprintf(stderr, "sweeptrace: error: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "sweeptrace: internal error: %s\n", e.what());
        return 3;
    }
    return exit_code;
}
