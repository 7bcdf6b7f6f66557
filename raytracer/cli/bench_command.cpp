#include "raytracer/cli/commands.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace {

// Registered so the CLI's shape is fixed; filled in by its own issue.
void add_bench_command(CLI::App& app, int& exit_code) {
    auto* cmd = app.add_subcommand("bench", "bench");
    cmd->callback([&exit_code] { throw InputError("bench: not built yet"); exit_code = 1; });
}

}  // namespace sweeptrace
