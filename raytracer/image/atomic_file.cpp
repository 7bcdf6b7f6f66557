#include "raytracer/image/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <climits>
#include <cstring>
#include <string>
#include <system_error>

#include "raytracer/input_error.hpp"

namespace sweeptrace {
namespace {

// Temporaries being written, in fixed storage a signal handler may read: a slot is claimed by
// setting `used` after its path is complete, and released before the path is reused.
struct Slot {
    std::atomic<bool> used{false};
    std::atomic<bool> claimed{false};
    char path[PATH_MAX + 1] = {};
};
std::array<Slot, 16> g_slots;

class InProgress {
public:
    explicit InProgress(const std::filesystem::path& temp) {
        const std::string& s = temp.native();
        if (s.size() > PATH_MAX) return;
        for (Slot& slot : g_slots) {
            bool expected = false;
            if (!slot.claimed.compare_exchange_strong(expected, true)) continue;
            std::memcpy(slot.path, s.c_str(), s.size() + 1);
            slot.used.store(true);
            slot_ = &slot;
            return;
        }
    }
    ~InProgress() {
        if (!slot_) return;
        slot_->used.store(false);
        slot_->claimed.store(false);
    }
    InProgress(const InProgress&) = delete;
    InProgress& operator=(const InProgress&) = delete;

private:
    Slot* slot_ = nullptr;
};

std::string temporary_prefix(const std::filesystem::path& path) {
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "." + std::string.
    std::string name(1, '.');
    name += path.filename().string();
    name += ".tmp-";
    return name;
}

// O_EXCL makes the name ours even when two processes write beside each other; the mode is
// filtered by the umask like any ordinary file (mkstemp would force 0600 onto the final file).
std::filesystem::path create_temporary_beside(const std::filesystem::path& path) {
    static std::atomic<unsigned> counter{0};
    const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    for (int attempt = 0; attempt < 100; ++attempt) {
        const std::filesystem::path temp =
            dir / (temporary_prefix(path) + std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1)));
        const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            ::close(fd);
            return temp;
        }
        if (errno != EEXIST)
            throw InputError("cannot write '" + path.string() + "': cannot create a file in '" + dir.string() +
                             "': " + reason_or(std::strerror(errno), "open failed"));
    }
    throw InputError("cannot write '" + path.string() + "': no free temporary name in '" + dir.string() + "'");
}

// "PID-N" with both parts decimal; the PID, or 0 when the suffix is not of that form.
pid_t pid_of_suffix(const std::string& suffix) {
    const std::size_t dash = suffix.find('-');
    if (dash == 0 || dash == std::string::npos || dash + 1 == suffix.size() || dash > 9) return 0;
    if (suffix.find_first_not_of("0123456789") != dash || suffix.find_first_not_of("0123456789", dash + 1) != std::string::npos)
        return 0;
    return static_cast<pid_t>(std::stol(suffix.substr(0, dash)));
}

}  // namespace

void remove_temporaries_in_progress() noexcept {
    for (Slot& slot : g_slots)
        if (slot.used.load()) ::unlink(slot.path);
}

int sweep_stale_temporaries(const std::filesystem::path& path) {
    const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    const std::string prefix = temporary_prefix(path);
    int removed = 0;
    std::error_code ec;
    for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.compare(0, prefix.size(), prefix) != 0) continue;
        const pid_t pid = pid_of_suffix(name.substr(prefix.size()));
        // Only a PID that is certainly gone: a live one (even reused) may be writing right now.
        if (pid <= 0 || pid == ::getpid() || ::kill(pid, 0) == 0 || errno != ESRCH) continue;
        std::error_code ignored;
        if (std::filesystem::remove(it->path(), ignored)) ++removed;
    }
    return removed;
}

void write_atomically(const std::filesystem::path& path,
                      const std::function<void(const std::filesystem::path& temp)>& write) {
    // The rename would put a regular file in place of a device, FIFO or folder: never. The
    // commands refuse such an output before any work (cli/output_guard.hpp); this is the last word.
    std::error_code ec;
    if (const std::filesystem::file_status st = std::filesystem::status(path, ec);
        std::filesystem::exists(st) && !std::filesystem::is_regular_file(st))
        throw InputError("cannot write '" + path.string() + "': it " + file_kind_problem(path));
    sweep_stale_temporaries(path);
    const std::filesystem::path temp = create_temporary_beside(path);
    const InProgress registered(temp);
    try {
        write(temp);
        if (::rename(temp.c_str(), path.c_str()) != 0)
            throw InputError("cannot write '" + path.string() + "': " + reason_or(std::strerror(errno), "rename failed"));
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(temp, ignored);
        throw;
    }
}

}  // namespace sweeptrace
