#pragma once
// pbrt-v4 scene files (pbrt.org/fileformat-v4) translated to our scene JSON, the one format the
// renderer loads (load_scene.hpp): `sweeptrace render scene.pbrt` converts in memory,
// `sweeptrace convert scene.pbrt -o scene.json` writes the translation. What is supported,
// approximated and ignored: docs/pbrt-import.md. Malformed input throws InputError naming
// file:line; everything approximated or ignored is a warning (one per kind), an error under strict.
#include <filesystem>
#include <string>
#include <vector>

#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

struct PbrtConversion {
    std::string json_text;              // the scene JSON, file names relative to the output folder
    std::vector<std::string> warnings;  // "<file>:<line>: <what was done instead>"
    std::string film_filename;          // the Film's "filename" (pbrt's default "pbrt.exr")
    std::vector<std::filesystem::path> input_files;  // every file read, with `validate` (read_files.hpp)
};

// `output`: the JSON file the text is meant for (its relative file names start from its folder).
// With `validate`, the JSON is also loaded as load_scene would load that file (meshes, images and
// all), so a translation the renderer would refuse fails here, before anything is written.
PbrtConversion convert_pbrt(const std::filesystem::path& file, const std::filesystem::path& output, bool strict,
                            bool validate);

// The scene itself, as load_scene would read convert_pbrt's JSON written beside `file`.
Scene load_pbrt_scene(const std::filesystem::path& file, bool strict, std::vector<std::string>& warnings,
                      std::string* film_filename = nullptr);

// True when `file` names a pbrt scene (extension .pbrt, any case, or .pbrt.gz: read inflated).
bool is_pbrt_file(const std::filesystem::path& file);

}  // namespace sweeptrace
