#pragma once
// The scene error tests' check: a bad scene must throw InputError whose message starts with the
// file it is about; the message is returned for the caller's checks of where and what.
#include <catch2/catch.hpp>

#include <string>

#include "raytracer/input_error.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "scene_test_files.hpp"

namespace sweeptrace::test {

// Loads `text` from a fresh file and returns the InputError message; fails the test if it loads.
inline std::string load_error(const TempDir& dir, const std::string& text) {
    const auto file = dir.write("bad.json", text);
    try {
        load_scene(file);
    } catch (const InputError& e) {
        const std::string message = e.what();
        // Every message starts with the file it is about.
        CHECK(message.rfind(file.string(), 0) == 0);
        return message;
    }
    FAIL("expected InputError for:\n" << text);
    return {};
}

}  // namespace sweeptrace::test
