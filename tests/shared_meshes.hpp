#pragma once
// Tests that read the shared meshes (../shared/meshes beside the checkout, or
// -DSWEEPTRACE_SHARED_DIR) start with `if (!shared_meshes_available()) return;`. A fresh clone
// of this repository alone has no ../shared: under ctest such a test then exits with ctest's
// SKIP_RETURN_CODE (tests/CMakeLists.txt passes it in SWEEPTRACE_SKIP_RETURN_CODE) after saying
// what it needs, and ctest reports it skipped; run by hand, it prints the same and returns. With
// CI=true a missing ../shared is a failure: CI must test the meshes.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace sweeptrace::test {

inline std::filesystem::path shared_meshes_dir() { return std::filesystem::path(SWEEPTRACE_SHARED_DIR) / "meshes"; }

inline bool shared_meshes_available() {
    const std::filesystem::path dir = shared_meshes_dir();
    std::error_code ec;
    if (std::filesystem::is_directory(dir, ec)) return true;
    const std::string need = "this test needs the shared meshes in " + dir.string() +
                             " (the shared/ folder beside the checkout; -DSWEEPTRACE_SHARED_DIR=... points elsewhere)";
    const char* ci = std::getenv("CI");
    if (ci && std::string(ci) == "true") throw std::runtime_error("CI=true and " + need);
    std::printf("SKIPPED: %s\n", need.c_str());
    std::fflush(stdout);
    if (const char* code = std::getenv("SWEEPTRACE_SKIP_RETURN_CODE")) std::_Exit(std::atoi(code));
    return false;
}

}  // namespace sweeptrace::test
