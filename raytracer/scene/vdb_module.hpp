#pragma once
// The VDB reader module, opened when a scene first needs it. Linking OpenVDB into the executable
// made every process resolve libopenvdb's and its dependencies' ~60000 symbol relocations at
// start (Debian builds libopenvdb with BIND_NOW): 0.05 s of CPU for `sweeptrace diff` as for a
// render of a scene without media. So vdb_reader.cpp, the one file that includes OpenVDB and
// NanoVDB, is built as sweeptrace-vdb.so, and the executable dlopens it on the first `vdb`
// medium (or pbrt-v4 `nanovdb` medium); vdb_module_abi.hpp is the interface between them.
//
// Where: beside the running executable (the folder of /proc/self/exe), where the build puts it
// next to `sweeptrace` (and a copy next to the test binary). The project has no install rules;
// a `sweeptrace` copied elsewhere needs the module beside it, and says so when a scene asks.
//
// Once: std::call_once opens it for the whole process, whichever thread asks first; the outcome
// (the table, or why not) is kept and every later call returns it. Never closed: the module
// holds OpenVDB's process-wide registries, it costs nothing once loaded, and the process's exit
// unloads it.
#include <filesystem>

#include "raytracer/scene/vdb_module_abi.hpp"

namespace sweeptrace {

// Where the module is looked for: the running executable's folder / kVdbModuleFile; empty when
// /proc/self/exe cannot be read.
std::filesystem::path vdb_module_path();

// The module's table, opened on the first call. Throws InputError "the VDB reader module <path>
// did not load: <dlerror()>" (missing, not loadable, no entry point, or built for another
// interface version), the same message at every call.
const SweeptraceVdbModule& vdb_module();

}  // namespace sweeptrace
