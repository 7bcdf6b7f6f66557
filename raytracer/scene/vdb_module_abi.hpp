#pragma once
// The boundary between the executable and the VDB reader module (sweeptrace-vdb.so, built from
// vdb_reader.cpp), which the executable opens only when a scene has a `vdb` medium
// (vdb_module.hpp says why and how). Plain C data both ways, so that no OpenVDB type, no C++
// object and no exception crosses it:
//   - the executable passes the file's and the grid's names and a sink of callbacks;
//   - the module reads the file's metadata, asks the sink to charge what the library will
//     allocate (`charge`) and for the dense buffer of the grid's active box (`dense`, which the
//     executable checks, charges to the load budget and allocates: the budget stays the
//     executable's, charged before allocation), fills that buffer, and returns the file's
//     index-to-world map;
//   - every failure inside the module (the libraries' exceptions included) ends at its entry
//     points: the module calls `fail` with the reason and returns nonzero. A refused charge or
//     buffer returns nonzero from the callback; the module then stops and returns nonzero
//     without a reason of its own (the executable holds the budget's message).
// Callbacks never throw. A change to these structs changes kVdbModuleAbi, so a module left
// over from another build is refused by its number instead of misread.
#include <cstdint>

extern "C" {

struct SweeptraceVdbSink {
    void* context;
    // Charge `bytes`, which the library is about to allocate, described by `what` (a grid's
    // part: `grid "density" (its sparse tree)`). 0: granted; nonzero: refused.
    int (*charge)(void* context, std::uint64_t bytes, const char* what);
    // The dense buffer of the index box [lo, hi] (inclusive), x fastest, then y, then z; null
    // when refused (too large, over the budget).
    float* (*dense)(void* context, const std::int64_t lo[3], const std::int64_t hi[3]);
    // One grid name of the file (vdb_grid_names).
    void (*name)(void* context, const char* name);
    // The reason the call failed, one line, without the file's name.
    void (*fail)(void* context, const char* reason);
};

struct SweeptraceVdbModule {
    std::uint32_t abi;
    // The float grid `grid` of `file` into sink->dense's buffer; `index_to_world` receives the
    // file's affine index-to-world map as 16 doubles, column-major (column c, row r at 4c + r).
    // 0 on success.
    int (*read_density)(const char* file, const char* grid, const SweeptraceVdbSink* sink, double index_to_world[16]);
    // Every grid name of `file` through sink->name, from its metadata (no voxels read). 0 on success.
    int (*grid_names)(const char* file, const SweeptraceVdbSink* sink);
};

// The module's one exported symbol.
const SweeptraceVdbModule* sweeptrace_vdb_module();
}

namespace sweeptrace {
inline constexpr std::uint32_t kVdbModuleAbi = 1;
inline constexpr const char* kVdbModuleSymbol = "sweeptrace_vdb_module";
inline constexpr const char* kVdbModuleFile = "sweeptrace-vdb.so";
}  // namespace sweeptrace
