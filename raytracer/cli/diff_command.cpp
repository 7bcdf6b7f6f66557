#include "raytracer/cli/commands.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace {

// Replaced by the image diff tool (issue 4).
void add_diff_command(CLI::App& app, int& exit_code) {
    auto* cmd = app.add_subcommand("diff", "Compare two images");
    cmd->callback([&exit_code] { throw InputError("diff: not built yet"); exit_code = 1; });
}

}  // namespace sweeptrace
