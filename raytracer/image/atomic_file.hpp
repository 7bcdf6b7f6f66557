#pragma once
// Writing a file so that readers see either the old file or the complete new one, never a
// partial one: write a temporary file in the same directory (same file system), then rename.
//
// The temporary is `.NAME.tmp-PID-N` beside NAME. It is removed on every exit the process
// controls: a failed write (exception), and a second SIGINT/SIGTERM during the write
// (cli/interrupt.cpp calls remove_temporaries_in_progress). What a SIGKILL or a power cut leaves
// behind is swept by the next write of NAME into that folder: a `.NAME.tmp-PID-N` whose PID is
// no running process is removed.
#include <filesystem>
#include <functional>

namespace sweeptrace {

// An existing `path` that is not a regular file (symlinks followed: a device, FIFO, folder) is
// refused with InputError and left alone. Otherwise:
// creates an empty, uniquely named temporary file beside `path`, calls `write(temp)`, and renames
// the temporary over `path`. If `write` throws or the rename fails, the temporary is removed and
// `path` is left exactly as it was; errors are rethrown (std::filesystem / write errors as
// InputError naming `path`).
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(const std::filesystem::path& temp)>& write);

// Async-signal-safe: unlinks the temporary file of every write_atomically in progress.
void remove_temporaries_in_progress() noexcept;

// Removes `.NAME.tmp-PID-N` files beside `path` (NAME = its file name) whose PID is not a running
// process; returns how many. write_atomically calls it before each write.
int sweep_stale_temporaries(const std::filesystem::path& path);

}  // namespace sweeptrace
