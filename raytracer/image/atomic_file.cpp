#include "raytracer/image/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>

#include "raytracer/input_error.hpp"

namespace sweeptrace {
namespace {

// O_EXCL makes the name ours even when two processes write beside each other; the mode is
// filtered by the umask like any ordinary file (mkstemp would force 0600 onto the final file).
std::filesystem::path create_temporary_beside(const std::filesystem::path& path) {
    static std::atomic<unsigned> counter{0};
    const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    for (int attempt = 0; attempt < 100; ++attempt) {
        // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "." + std::string.
        std::string name(1, '.');
        name += path.filename().string();
        name += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1));
        const std::filesystem::path temp = dir / name;
        const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            ::close(fd);
            return temp;
        }
        if (errno != EEXIST)
            throw InputError("cannot write '" + path.string() + "': cannot create a file in '" + dir.string() +
                             "': " + std::strerror(errno));
    }
    throw InputError("cannot write '" + path.string() + "': no free temporary name in '" + dir.string() + "'");
}

}  // namespace

void write_atomically(const std::filesystem::path& path,
                      const std::function<void(const std::filesystem::path& temp)>& write) {
    const std::filesystem::path temp = create_temporary_beside(path);
    try {
        write(temp);
        if (::rename(temp.c_str(), path.c_str()) != 0)
            throw InputError("cannot write '" + path.string() + "': " + std::strerror(errno));
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(temp, ignored);
        throw;
    }
}

}  // namespace sweeptrace
