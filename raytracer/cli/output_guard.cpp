#include "raytracer/cli/output_guard.hpp"

#include <sys/stat.h>

#include <optional>
#include <system_error>
#include <utility>

#include "raytracer/input_error.hpp"

namespace sweeptrace {
namespace {

namespace fs = std::filesystem;

// Device and inode of an existing file, symlinks followed; none when it does not exist.
std::optional<std::pair<dev_t, ino_t>> identity(const fs::path& p) {
    struct stat st {};
    if (::stat(p.c_str(), &st) != 0) return std::nullopt;
    return std::make_pair(st.st_dev, st.st_ino);
}

// The directory entry a write of `p` replaces (write_atomically renames onto the name itself):
// its folder resolved through symlinks and "..", plus its name.
fs::path entry(const fs::path& p) {
    std::error_code ec;
    const fs::path abs = fs::absolute(p, ec);
    const fs::path folder = fs::weakly_canonical(abs.parent_path(), ec);
    return (ec ? abs.parent_path() : folder) / abs.filename();
}

std::string named(const NamedFile& f) { return f.role + " '" + f.path.string() + "'"; }

void check_one(const NamedFile& out) {
    std::error_code ec;
    const fs::path folder = fs::absolute(out.path, ec).parent_path();
    if (!fs::is_directory(folder, ec))
        throw InputError(named(out) + ": directory '" + out.path.parent_path().string() + "' does not exist");
    const fs::file_status st = fs::status(out.path, ec);
    if (fs::exists(st) && !fs::is_regular_file(st))
        throw InputError(named(out) + " " + file_kind_problem(out.path) +
                         "; outputs are written as regular files and a non-regular one is never replaced (to discard "
                         "an output, write it into a temporary folder)");
}

}  // namespace

void check_outputs(const std::vector<NamedFile>& outputs, const std::vector<NamedFile>& inputs) {
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const NamedFile& out = outputs[i];
        if (out.path.empty()) continue;
        check_one(out);
        const auto id = identity(out.path);
        const fs::path where = entry(out.path);
        for (std::size_t j = 0; j < i; ++j) {
            const NamedFile& other = outputs[j];
            if (other.path.empty()) continue;
            const auto other_id = identity(other.path);
            if (entry(other.path) == where || (id && other_id && *id == *other_id))
                throw InputError(named(out) + " is the same file as " + named(other) +
                                 "; one would overwrite the other, give each output its own path");
        }
        if (!id) continue;  // an output that does not exist yet cannot be an input
        for (const NamedFile& in : inputs)
            if (identity(in.path) == id)  // device and inode: hard links, symlinks, "./x", "a/../x"
                throw InputError(named(out) + " is the " + named(in) +
                                 " (the same file); writing it would destroy an input, choose another output path");
    }
}

}  // namespace sweeptrace
