#pragma once
// Writing a file so that readers see either the old file or the complete new one, never a
// partial one: write a temporary file in the same directory (same file system), then rename.
#include <filesystem>
#include <functional>

namespace sweeptrace {

// Creates an empty, uniquely named temporary file beside `path`, calls `write(temp)`, and renames
// the temporary over `path`. If `write` throws or the rename fails, the temporary is removed and
// `path` is left exactly as it was; errors are rethrown (std::filesystem / write errors as
// InputError naming `path`).
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(const std::filesystem::path& temp)>& write);

}  // namespace sweeptrace
