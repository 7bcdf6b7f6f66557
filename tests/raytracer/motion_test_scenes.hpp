#pragma once
// Scenes with moving objects for the motion blur tests, written as JSON (so the loader's keys are
// what is exercised) into a test's temporary directory.
#include <string>

#include "raytracer/scene/load_scene.hpp"
#include "scene_test_files.hpp"

namespace sweeptrace::test {

// A unit cube, for a moving mesh instance.
inline const char* const kCubeObj =
    "v -0.5 -0.5 -0.5\nv 0.5 -0.5 -0.5\nv 0.5 0.5 -0.5\nv -0.5 0.5 -0.5\n"
    "v -0.5 -0.5 0.5\nv 0.5 -0.5 0.5\nv 0.5 0.5 0.5\nv -0.5 0.5 0.5\n"
    "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 4 7 3\nf 4 8 7\nf 1 5 8\nf 1 8 4\nf 2 3 7\nf 2 7 6\n";

// Objects moving every way the format allows, lit by a quad light and a sky: a sphere
// translating, a box rotating through three keyframes, a cylinder scaling and turning, a cube
// mesh rotating and translating, a still floor. `moving` false writes the same scene
// with every object at its shutter-open pose and no shutter; `zero_motion` keeps the motion
// blocks and the shutter but makes every keyframe the same pose.
inline std::string motion_scene_text(int width, int height, bool moving = true, bool zero_motion = false) {
    auto close = [&](const std::string& still, const std::string& moved) {
        if (!moving) return std::string();
        return ", \"motion\": { \"close\": " + (zero_motion ? still : moved) + " }";
    };
    const std::string sphere_at = R"([{ "translate": [-1.2, 0.6, 0] }])";
    const std::string box_keys = zero_motion
        ? R"([[{ "translate": [0.2, 0.5, -0.5] }], [{ "translate": [0.2, 0.5, -0.5] }], [{ "translate": [0.2, 0.5, -0.5] }]])"
        : R"([[{ "translate": [0.2, 0.5, -0.5] }],
             [{ "rotate": { "axis": [0, 1, 0], "degrees": 40 } }, { "translate": [0.3, 0.6, -0.5] }],
             [{ "rotate": { "axis": [0, 1, 0], "degrees": 80 } }, { "translate": [0.4, 0.5, -0.5] }]])";
    const std::string box = moving ? R"(, "motion": { "keyframes": )" + box_keys + " }"
                                   : R"(, "transform": [{ "translate": [0.2, 0.5, -0.5] }])";
    const std::string cyl_at = R"([{ "translate": [1.3, 0.5, 0.3] }])";
    const std::string mesh_at = R"([{ "scale": 0.7 }, { "translate": [-0.2, 0.4, 1.0] }])";
    return std::string(R"({
  "camera": { "position": [0, 2, 6], "look_at": [0, 0.4, 0], "fov": 40)") +
           (moving ? R"(, "shutter": [0, 1])" : "") + R"( },
  "film": { "width": )" + std::to_string(width) + R"(, "height": )" + std::to_string(height) + R"(, "spp": 8, "max_depth": 4 },
  "background": { "sky": { "horizon": [0.8, 0.8, 0.8], "zenith": [0.3, 0.4, 0.7] } },
  "materials": {
    "grey": { "type": "diffuse", "albedo": [0.5, 0.5, 0.5] },
    "red": { "type": "diffuse", "albedo": [0.7, 0.2, 0.1] },
    "metal": { "type": "metal", "albedo": [0.9, 0.8, 0.6], "roughness": 0.3 },
    "lamp": { "type": "emissive", "emission": [6, 6, 6] }
  },
  "objects": [
    { "type": "quad", "corner": [-5, 0, -5], "edge_u": [0, 0, 10], "edge_v": [10, 0, 0], "material": "grey" },
    { "type": "quad", "corner": [-1, 3, -1], "edge_u": [2, 0, 0], "edge_v": [0, 0, 2], "material": "lamp" },
    { "type": "sphere", "center": [0, 0, 0], "radius": 0.5, "material": "red", "transform": )" + sphere_at +
           close(sphere_at, R"([{ "translate": [-0.4, 0.6, 0.2] }])") + R"( },
    { "type": "box", "center": [0, 0, 0], "size": [0.8, 0.8, 0.8], "material": "metal")" + box + R"( },
    { "type": "cylinder", "center": [0, 0, 0], "radius": 0.3, "height": 0.8, "material": "grey", "transform": )" + cyl_at +
           close(cyl_at, R"([{ "scale": [1.3, 1, 1] }, { "rotate": { "axis": [1, 0, 0], "degrees": 30 } }, { "translate": [1.3, 0.6, 0.3] }])") + R"( },
    { "type": "mesh", "file": "cube.obj", "material": "red", "transform": )" + mesh_at +
           close(mesh_at, R"([{ "scale": 0.7 }, { "rotate": { "axis": [0, 1, 1], "degrees": 60 } }, { "translate": [0.3, 0.4, 1.1] }])") + R"( }
  ]
}
)";
}

inline Scene load_motion_scene(const TempDir& dir, int width, int height, bool moving = true, bool zero_motion = false) {
    dir.write("cube.obj", kCubeObj);
    return load_scene(dir.write("motion.json", motion_scene_text(width, height, moving, zero_motion)));
}

}  // namespace sweeptrace::test
