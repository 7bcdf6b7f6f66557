#include "raytracer/scene/vdb_grid.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>

#include "raytracer/input_error.hpp"
#include "raytracer/load_budget.hpp"
#include "raytracer/scene/read_files.hpp"
#include "raytracer/scene/vdb_module.hpp"

namespace sweeptrace {

namespace {

// Largest dense axis: the `grid` medium's own (scene/load_media.cpp), so that a sample's index
// stays exact in the float lookup.
constexpr std::int64_t kMaxVdbAxis = std::int64_t{1} << 24;

// One call into the module: the sink's context. `error` is the whole message ("<file>: ...")
// of the first refusal or failure.
struct VdbCall {
    const std::filesystem::path& file;
    std::string grid;  // quoted, for messages
    std::string what;
    VdbDensity* out = nullptr;
    std::vector<std::string>* names = nullptr;
    std::array<std::int64_t, 3> lo{};
    std::string error;
};

VdbCall& call_of(void* context) { return *static_cast<VdbCall*>(context); }

// A callback's body, with everything it may throw kept on this side of the module: the
// message is kept for read_vdb_density to throw once the module has returned.
template <class F>
auto guarded(VdbCall& c, F body, decltype(body()) refused) noexcept -> decltype(body()) {
    try {
        return body();
    } catch (const std::exception& e) {
        if (c.error.empty()) c.error = e.what();
    } catch (...) {
    }
    return refused;
}

int vdb_charge(void* context, std::uint64_t bytes, const char* what) noexcept {
    VdbCall& c = call_of(context);
    return guarded(c, [&] {
        charge_load_memory(bytes, c.file.string(), c.what + "'s " + what);
        return 0;
    }, 1);
}

// The dense box [lo, hi]: its size checked and charged to the budget before it is allocated.
float* vdb_dense(void* context, const std::int64_t lo[3], const std::int64_t hi[3]) noexcept {
    VdbCall& c = call_of(context);
    return guarded(c, [&]() -> float* {
        VdbDensity& out = *c.out;
        std::array<std::int64_t, 3> n{};
        for (int a = 0; a < 3; ++a) n[a] = hi[a] - lo[a] + 1;
        const std::string dims = std::to_string(n[0]) + " x " + std::to_string(n[1]) + " x " + std::to_string(n[2]);
        for (int a = 0; a < 3; ++a)
            if (n[a] < 1 || n[a] > kMaxVdbAxis)
                throw InputError(c.file.string() + ": grid " + c.grid + "'s active box is " + dims +
                                 " voxels; each side must be at most " + std::to_string(kMaxVdbAxis));
        // Under the 2^72 bytes of three 2^24 axes, a double holds the product; past 2^64 bytes
        // the charge is refused anyway, at its largest figure.
        const double bytes = double(n[0]) * double(n[1]) * double(n[2]) * double(sizeof(float));
        const auto charge = bytes < 1.8e19 ? static_cast<std::uint64_t>(bytes) : std::numeric_limits<std::uint64_t>::max();
        charge_load_memory(charge, c.file.string(), c.what + "'s grid " + c.grid + " (its active box, " + dims + " voxels, dense)");
        out.nx = static_cast<int>(n[0]);
        out.ny = static_cast<int>(n[1]);
        out.nz = static_cast<int>(n[2]);
        for (int a = 0; a < 3; ++a) {
            c.lo[a] = lo[a];
            out.p0[a] = static_cast<float>(lo[a]) - 0.5f;
            out.p1[a] = static_cast<float>(hi[a]) + 0.5f;
        }
        out.density.resize(static_cast<std::size_t>(n[0]) * static_cast<std::size_t>(n[1]) * static_cast<std::size_t>(n[2]));
        return out.density.data();
    }, nullptr);
}

void vdb_name(void* context, const char* name) noexcept {
    VdbCall& c = call_of(context);
    guarded(c, [&] {
        c.names->push_back(name);
        return 0;
    }, 1);
}

void vdb_fail(void* context, const char* reason) noexcept {
    VdbCall& c = call_of(context);
    guarded(c, [&] {
        if (c.error.empty()) c.error = c.file.string() + ": " + reason;
        return 0;
    }, 1);
}

SweeptraceVdbSink sink_of(VdbCall& c) { return {&c, vdb_charge, vdb_dense, vdb_name, vdb_fail}; }

// Every voxel a density: >= 0 and finite (the first one that is not, by its index coordinate).
void check_vdb_values(const VdbDensity& d, const std::array<std::int64_t, 3>& lo, const std::filesystem::path& file,
                      const std::string& grid) {
    for (std::size_t i = 0; i < d.density.size(); ++i) {
        const float v = d.density[i];
        if (v >= 0.0f && std::isfinite(v)) continue;
        const std::size_t x = i % std::size_t(d.nx), y = i / std::size_t(d.nx) % std::size_t(d.ny),
                          z = i / (std::size_t(d.nx) * std::size_t(d.ny));
        throw InputError(file.string() + ": grid \"" + excerpt(grid) + "\"'s voxel (" + std::to_string(lo[0] + std::int64_t(x)) +
                         ", " + std::to_string(lo[1] + std::int64_t(y)) + ", " + std::to_string(lo[2] + std::int64_t(z)) +
                         ") is " + std::to_string(v) + "; a density must be >= 0 and finite");
    }
}

}  // namespace

VdbDensity read_vdb_density(const std::filesystem::path& file, const std::string& grid, const std::string& what) {
    if (const std::string problem = file_kind_problem(file); !problem.empty()) throw InputError(file.string() + ": " + problem);
    note_read_file(file);
    const SweeptraceVdbModule* module = nullptr;
    try {
        module = &vdb_module();
    } catch (const InputError& e) {
        throw InputError(file.string() + ": cannot be read: " + e.what());
    }
    VdbDensity out;
    VdbCall call{file, "\"" + excerpt(grid) + "\"", what, &out, nullptr, {}, {}};
    const SweeptraceVdbSink sink = sink_of(call);
    double m[16] = {};
    if (module->read_density(file.c_str(), grid.c_str(), &sink, m) != 0)
        throw InputError(!call.error.empty() ? call.error : file.string() + ": the VDB reader failed without a reason (out of memory)");
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) out.index_to_world[c][r] = m[4 * c + r];
    check_vdb_values(out, call.lo, file, grid);
    return out;
}

std::vector<std::string> vdb_grid_names(const std::filesystem::path& file) {
    std::vector<std::string> names;
    if (!file_kind_problem(file).empty()) return names;
    try {
        const SweeptraceVdbModule& module = vdb_module();
        VdbCall call{file, {}, {}, nullptr, &names, {}, {}};
        const SweeptraceVdbSink sink = sink_of(call);
        if (module.grid_names(file.c_str(), &sink) != 0 || !call.error.empty()) names.clear();
    } catch (const InputError&) {
        names.clear();  // read_vdb_density says why, when the medium is loaded
    }
    return names;
}

}  // namespace sweeptrace
