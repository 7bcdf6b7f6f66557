#pragma once
// The accuracy table as CSV (for the charts) and Markdown (for docs/), and on stdout.
#include <filesystem>
#include <functional>
#include <ostream>
#include <vector>

#include "raytracer/accuracy/run.hpp"

namespace sweeptrace::accuracy {

void write_csv(std::ostream& out, const std::vector<Metrics>& rows);
void write_markdown(std::ostream& out, const std::vector<Metrics>& rows);

// Writes through write_atomically (image/atomic_file.hpp): a failed run never leaves a partial
// or half-overwritten table. Throws InputError naming the path when it cannot be written.
void save_file(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write);

// Fails early (InputError naming the path) when `path` could not be written later: its
// directory is missing. Called before a long run, so a typo costs nothing.
void check_writable(const std::filesystem::path& path);

}  // namespace sweeptrace::accuracy
