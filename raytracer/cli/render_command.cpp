#include "raytracer/cli/commands.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace {

// Replaced by the renderer (issue 3); registered so the CLI's shape is fixed from the start.
void add_render_command(CLI::App& app, int& exit_code) {
    auto* cmd = app.add_subcommand("render", "Render a JSON scene to an image");
    cmd->callback([&exit_code] { throw InputError("render: the renderer is not built yet"); exit_code = 1; });
}

}  // namespace sweeptrace
