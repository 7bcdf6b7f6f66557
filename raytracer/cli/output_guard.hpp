#pragma once
// The one rule for every file a command writes (render's image, --variance, --forensics and its
// picture; merge -o; convert -o; reference-check's table and pictures; diff's --heatmap, --json,
// --junit and --html pages). A command hands check_outputs every output and every file it reads,
// before any work that the outputs would be the result of; a new output joins the rule by being
// in that list (one line where the command builds it).
//
// For each output:
// - its folder exists;
// - if it exists, it is a regular file (symlinks followed): a directory, device (/dev/null,
//   /dev/full), FIFO or socket is refused, never replaced: the atomic write (image/atomic_file.hpp)
//   renames a new regular file over the name, which would put a file in place of /dev/null, and a
//   FIFO would block. To discard an output, write it into a temporary folder;
// - it is no other output: two outputs are the same when they name the same directory entry
//   (the folder resolved through symlinks and "..", plus the name: "x.exr" and "./x.exr"), or
//   when both exist and are one file (device and inode: symlinks and hard links);
// - it is no input: an existing output that is, by device and inode, a file the command reads.
// Violations throw InputError naming the output's option and path, and the other file.
#include <filesystem>
#include <string>
#include <vector>

namespace sweeptrace {

// A file and what the command calls it in a message: "output" (-o), "--variance", "scene",
// "image A", "scene's input", ...
struct NamedFile {
    std::string role;
    std::filesystem::path path;
};

// Throws InputError on the first output that breaks the rule above; outputs with an empty path
// are skipped (an option not given). Cheap (a stat per file and pair): commands that learn of more
// inputs later (the scene load's files) call it again with them.
void check_outputs(const std::vector<NamedFile>& outputs, const std::vector<NamedFile>& inputs = {});

}  // namespace sweeptrace
