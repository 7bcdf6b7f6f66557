#include "raytracer/cli/output_guard.hpp"

#include <system_error>

#include "raytracer/input_error.hpp"

namespace sweeptrace {

void refuse_output_over_input(const std::filesystem::path& out, const std::vector<NamedInput>& inputs) {
    std::error_code ec;
    if (!std::filesystem::exists(out, ec)) return;
    for (const NamedInput& in : inputs) {
        std::error_code e;
        if (std::filesystem::equivalent(out, in.path, e))  // device and inode: hard links, symlinks, "./x", "a/../x"
            throw InputError("output '" + out.string() + "' is the " + in.role + " '" + in.path.string() +
                             "' (the same file); writing it would destroy an input, choose another output path");
    }
}

}  // namespace sweeptrace
