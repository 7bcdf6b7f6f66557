#pragma once
// pbrt scenes written for the tests: the text in a temporary folder, converted to our JSON (as
// `sweeptrace convert` does, without loading it) or loaded as a Scene. The world is pbrt's either
// way; a camera that keeps pbrt's orientation (the default) becomes our left-handed camera
// (scene/pbrt/pbrt_world.hpp); kFlipped starts a scene with `Scale -1 1 1`, a right-handed one.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "raytracer/scene/pbrt/pbrt_import.hpp"
#include "scene_test_files.hpp"

namespace sweeptrace::test {

inline constexpr const char* kFlipped = "Scale -1 1 1\n";

struct Converted {
    nlohmann::json doc;
    std::vector<std::string> warnings;
};

inline Converted convert_text(const TempDir& dir, const std::string& text, bool strict = false) {
    const auto file = dir.write("scene.pbrt", text);
    const PbrtConversion c = convert_pbrt(file, dir.path() / "scene.json", strict, false);
    return {nlohmann::json::parse(c.json_text), c.warnings};
}

// A world block with one shape of material `white`, for tests of everything around it.
inline std::string world_with(const std::string& body) {
    return std::string("WorldBegin\nMakeNamedMaterial \"white\" \"string type\" \"diffuse\"\nNamedMaterial \"white\"\n") + body + "\n";
}

inline bool has_warning(const std::vector<std::string>& warnings, const std::string& part) {
    for (const std::string& w : warnings)
        if (w.find(part) != std::string::npos) return true;
    return false;
}

}  // namespace sweeptrace::test
