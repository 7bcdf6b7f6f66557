#pragma once
// An output path must not name one of the command's inputs: `render scene.json -o mesh.obj.png`
// is harmless, but `-o` (or diff's --heatmap) naming the scene, an OBJ the scene loads, or an
// image being compared would replace that input with the result. Compared by file identity
// (device and inode, through std::filesystem::equivalent), not by spelling, so "./a.png",
// "dir/../a.png", a symlink and a hard link to the input are all caught.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace sweeptrace {

struct NamedInput {
    std::string role;  // "scene", "mesh", "image A", ...
    std::filesystem::path path;
};

// Throws InputError "output '<out>' is the <role> '<path>' ..." when `out` exists and is the same
// file as any input; an output that does not exist yet cannot be one.
void refuse_output_over_input(const std::filesystem::path& out, const std::vector<NamedInput>& inputs);

}  // namespace sweeptrace
