#pragma once
// The readers take paths (as the program does), so each fuzz input is written to a file in a
// private folder (in /dev/shm when there is one: no disk I/O per run) and read back from there.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace sweeptrace::fuzz {

inline const std::filesystem::path& work_dir() {
    static const std::filesystem::path dir = [] {
        const std::filesystem::path base =
            std::filesystem::is_directory("/dev/shm") ? std::filesystem::path("/dev/shm") : std::filesystem::temp_directory_path();
        std::filesystem::path d = base / ("sweeptrace-fuzz-" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        return d;
    }();
    return dir;
}

// Writes the input to work_dir()/name and returns the path; aborts if it cannot (not a finding).
inline std::filesystem::path input_file(const std::string& name, const std::uint8_t* data, std::size_t size) {
    const std::filesystem::path p = work_dir() / name;
    std::FILE* f = std::fopen(p.c_str(), "wb");
    if (!f || std::fwrite(data, 1, size, f) != size || std::fclose(f) != 0) std::abort();
    return p;
}

}  // namespace sweeptrace::fuzz
