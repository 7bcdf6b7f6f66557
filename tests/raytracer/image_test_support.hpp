#pragma once
// Shared by the image tests: a scratch directory per test, running the built binary, and
// comparing images bit for bit.
#include <sys/wait.h>
#include <unistd.h>

#include <bit>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "raytracer/image/image.hpp"

namespace sweeptrace::testing {

// A fresh directory under the system temp dir, removed with everything in it on destruction.
class ScratchDir {
public:
    explicit ScratchDir(const std::string& tag) {
        static int counter = 0;
        path_ = std::filesystem::temp_directory_path() /
                ("sweeptrace-" + tag + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~ScratchDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;
    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

private:
    std::filesystem::path path_;
};

struct CommandResult {
    int exit_code = -1;
    std::string output;  // stdout and stderr together
};

inline std::string read_file_text(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

inline void write_file_text(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

// Runs `sweeptrace <arguments>` (the arguments go to the shell as written).
inline CommandResult run_sweeptrace(const std::string& arguments, const std::filesystem::path& scratch) {
    const std::filesystem::path log = scratch / "command-output.txt";
    const std::string command = std::string("\"") + SWEEPTRACE_BINARY_DIR + "/sweeptrace\" " + arguments + " >\"" +
                                log.string() + "\" 2>&1";
    const int status = std::system(command.c_str());
    CommandResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.output = read_file_text(log);
    return r;
}

// Same size and the same bits in every channel (so -0 differs from 0, and a NaN equals itself).
inline bool bitwise_equal(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height) return false;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            if (std::bit_cast<std::uint32_t>(a.pixels[i][c]) != std::bit_cast<std::uint32_t>(b.pixels[i][c])) return false;
    return true;
}

}  // namespace sweeptrace::testing
