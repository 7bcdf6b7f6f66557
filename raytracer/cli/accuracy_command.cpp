#include "raytracer/cli/commands.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace {

// Registered so the CLI's shape is fixed; filled in by its own issue.
void add_accuracy_command(CLI::App& app, int& exit_code) {
    auto* cmd = app.add_subcommand("accuracy", "accuracy");
    cmd->callback([&exit_code] { throw InputError("accuracy: not built yet"); exit_code = 1; });
}

}  // namespace sweeptrace
