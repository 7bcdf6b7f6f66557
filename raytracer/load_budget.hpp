#pragma once
// One memory budget for loading a scene. A small file can ask for a lot of memory: a 2 MB
// .ply.gz of 255-corner faces for 5.7 GB of triangles, six 1 MiB RLE TGAs claiming 8192 x 8192
// for 0.8 GB each, a pbrt parameter copied per attribute level. Each reader has its own limit,
// but nothing bounded the sum, so the load ended in bad_alloc (exit 3) or the OOM killer.
//
// Every large allocation of a load (mesh vertices and triangles, image pixels, environment map
// tables, the pbrt importer's parsed parameters) is charged here first, with the file and what it
// reads; the charge that would pass the limit throws InputError naming them, before allocating.
// The limit is --max-memory when given, else the memory available (available_memory() below says how
// that is found). A leaf: the image readers (image/) and the scene loaders (scene/) both charge it.
//
// The budget lives while a LoadBudgetScope does (the outermost one of a load, the others join
// it); outside one, charges are not counted. Loading is single-threaded; the state is per thread.
// Header-only, as input_error.hpp: the leaf has no library of its own.
#include <sys/resource.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <algorithm>
#include <optional>
#include <string>
#include <utility>

#include "raytracer/input_error.hpp"

namespace sweeptrace {

namespace load_budget_detail {

inline std::optional<std::uint64_t> read_number_file(const char* path) {
    std::ifstream in(path);
    std::uint64_t v = 0;
    if (in >> v) return v;
    return std::nullopt;  // missing, or "max"
}

inline std::optional<std::uint64_t> meminfo_available() {
    std::ifstream in("/proc/meminfo");
    std::string key, unit;
    std::uint64_t kb = 0;
    while (in >> key >> kb >> unit)
        if (key == "MemAvailable:") return kb * 1024;
    return std::nullopt;
}

// The address space this process already maps (/proc/self/statm's first field, in pages).
inline std::uint64_t mapped_bytes() {
    std::ifstream in("/proc/self/statm");
    std::uint64_t pages = 0;
    in >> pages;
    return pages * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
}

inline void lower(std::optional<std::uint64_t>& value, std::uint64_t bound) {
    if (!value || bound < *value) value = bound;
}

struct Budget {
    int depth = 0;  // open scopes
    bool limited = false;
    std::uint64_t limit = 0, used = 0;
};

inline thread_local Budget budget;
inline std::optional<std::uint64_t> configured_limit;

}  // namespace load_budget_detail

// The memory this process may still take: MemAvailable from /proc/meminfo, lowered to the
// cgroup's memory.max - memory.current and to 3/4 of the address space left under its limit
// (ulimit -v; the quarter is for what a load allocates beside its charges: parsers' buffers,
// decoders' rows, the allocator's slack); nullopt when none can be read.
inline std::optional<std::uint64_t> available_memory() {
    using namespace load_budget_detail;
    std::optional<std::uint64_t> avail = meminfo_available();
    const auto max = read_number_file("/sys/fs/cgroup/memory.max");
    const auto current = read_number_file("/sys/fs/cgroup/memory.current");
    if (max && current) lower(avail, *max > *current ? *max - *current : 0);
    rlimit as{};
    if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) {
        const std::uint64_t limit = as.rlim_cur, mapped = mapped_bytes();
        lower(avail, limit > mapped ? (limit - mapped) / 4 * 3 : 0);
    }
    return avail;
}

// "1.50 GB" style, for messages.
inline std::string byte_text(std::uint64_t bytes) {
    char buf[32];
    const double b = double(bytes);
    if (b >= 1e9) std::snprintf(buf, sizeof buf, "%.2f GB", b / 1e9);
    else if (b >= 1e6) std::snprintf(buf, sizeof buf, "%.1f MB", b / 1e6);
    else std::snprintf(buf, sizeof buf, "%.0f kB", b / 1e3);
    return buf;
}

// The limit of the loads that start after this call (--max-memory); nullopt: available_memory().
inline void set_load_memory_limit(std::optional<std::uint64_t> bytes) { load_budget_detail::configured_limit = bytes; }

class LoadBudgetScope {
public:
    LoadBudgetScope() : outermost_(load_budget_detail::budget.depth == 0) {
        using namespace load_budget_detail;
        ++budget.depth;
        if (!outermost_) return;
        const std::optional<std::uint64_t> limit = configured_limit ? configured_limit : available_memory();
        budget.limited = limit.has_value();
        budget.limit = limit.value_or(0);
        budget.used = 0;
    }
    ~LoadBudgetScope() {
        --load_budget_detail::budget.depth;
        if (outermost_) load_budget_detail::budget.used = 0;
    }
    LoadBudgetScope(const LoadBudgetScope&) = delete;
    LoadBudgetScope& operator=(const LoadBudgetScope&) = delete;

private:
    bool outermost_;
};

// Counts `bytes` against the current load's budget. Throws InputError "<file>: <what> needs X,
// which would bring the scene's data to Y, over the load budget of Z (...)" when it would pass it.
inline void charge_load_memory(std::uint64_t bytes, const std::string& file, const std::string& what) {
    using namespace load_budget_detail;
    if (budget.depth == 0) return;
    if (budget.limited && (bytes > budget.limit || budget.used > budget.limit - bytes))
        throw InputError(file + ": " + what + " needs " + byte_text(bytes) + ", which would bring the scene's data to " +
                         byte_text(budget.used + bytes) + ", over the load budget of " + byte_text(budget.limit) +
                         (configured_limit ? " (--max-memory)" : " (the memory available; --max-memory sets it)"));
    budget.used += bytes;
}

// Gives back `bytes` the current load was charged for a buffer it has freed, so that the budget
// bounds what a load holds at once, not all it ever held. No effect outside a load.
inline void release_load_memory(std::uint64_t bytes) {
    using namespace load_budget_detail;
    if (budget.depth == 0) return;
    budget.used -= std::min(bytes, budget.used);
}

// Charges for a buffer that lives only while a file is parsed (a .gz file's inflated bytes),
// given back when this is destroyed. Lives inside the load's scope, as the buffer does.
class TransientLoadCharge {
public:
    TransientLoadCharge() = default;
    ~TransientLoadCharge() { release_load_memory(bytes_); }
    TransientLoadCharge(TransientLoadCharge&& o) noexcept : bytes_(std::exchange(o.bytes_, 0)) {}
    TransientLoadCharge& operator=(TransientLoadCharge&& o) noexcept {
        release_load_memory(bytes_);
        bytes_ = std::exchange(o.bytes_, 0);
        return *this;
    }
    // charge_load_memory, and kept to be given back.
    void add(std::uint64_t bytes, const std::string& file, const std::string& what) {
        charge_load_memory(bytes, file, what);
        bytes_ += bytes;
    }

private:
    std::uint64_t bytes_ = 0;
};

// What the current load has been charged so far (0 outside a load): for tests.
inline std::uint64_t load_memory_charged() {
    return load_budget_detail::budget.depth == 0 ? 0 : load_budget_detail::budget.used;
}

}  // namespace sweeptrace
