#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace sweeptrace {

// Input size limits, checked on the file's size before a byte is read or parsed: a parser holds
// many times its input in memory (nlohmann: ~20 bytes per byte of JSON), so a 200 MB "scene" would
// take gigabytes and a minute before any message. The largest real inputs are far below: scenes
// are a few KB, the biggest mesh the tests use is 3.7 MB.
inline constexpr std::uintmax_t kMaxSceneFileBytes = std::uintmax_t{16} << 20;   // 16 MiB
inline constexpr std::uintmax_t kMaxMeshFileBytes = std::uintmax_t{512} << 20;   // 512 MiB

// A size in messages: whole MiB, rounded up ("16 MiB").
std::string mib_text(std::uintmax_t bytes);

// Throws InputError "<file>: cannot read <what>: <reason>" unless `file` is a regular file of at
// most `max_bytes` (so also for a missing file, a directory, a FIFO or a device).
void check_input_file(const std::filesystem::path& file, const char* what, std::uintmax_t max_bytes);

// The whole file as bytes, after check_input_file. Throws InputError as above, or when reading fails.
std::string read_text_file(const std::filesystem::path& file, const char* what,
                           std::uintmax_t max_bytes = kMaxSceneFileBytes);

// The words of one line separated by spaces and tabs only (as tinyobjloader separates an OBJ's, and
// as PLY headers and ASCII data are written); the views point into `line`.
std::vector<std::string_view> words(std::string_view line);

}  // namespace sweeptrace
