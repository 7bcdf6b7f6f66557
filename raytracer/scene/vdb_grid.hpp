#pragma once
// A float density grid read from an OpenVDB (.vdb) or NanoVDB (.nvdb) file, as the dense grid the
// `grid` medium renders (scene/medium.hpp): the voxels of the grid's active bounding box, x
// fastest. OpenVDB stores a voxel's value at its integer index coordinate (the voxel's centre), so
// the dense samples sit at the voxel centres of the index-space box [min - 1/2, max + 1/2], which
// is exactly where a `grid` medium puts its samples; the file's index-to-world transform (affine
// only) is returned for the caller to compose with the medium's own. Which format a file is comes
// from its first bytes, not its name.
//
// The libraries are not linked: the reading is done by the VDB reader module (vdb_reader.cpp,
// the only file that includes OpenVDB and NanoVDB), opened on the first call (vdb_module.hpp);
// its failures come back as InputError "<file>: <what>", and a module that cannot be loaded is
// one too ("<file>: cannot be read: the VDB reader module <path> did not load: <dlerror>").
// Before any voxel is read, the dense grid (and, for OpenVDB, the sparse tree the file says it
// needs in memory) is charged to the load budget (load_budget.hpp) here, from the file's
// metadata as the module reports it, and only then allocated here, so a small file claiming a
// huge box is refused with its figures. Errors: not a file of either format, truncated or
// corrupt, no grid of that name (the message lists the names there), a grid of another value
// type than float, no active voxels, a non-affine (frustum) transform, a background value other
// than 0 (a density outside the active voxels, which the dense box could not hold), a negative
// or non-finite voxel.
#include <filesystem>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace sweeptrace {

struct VdbDensity {
    int nx = 0, ny = 0, nz = 0;
    std::vector<float> density;          // nx x ny x nz, x fastest, then y, then z
    glm::vec3 p0{0.0f}, p1{0.0f};        // the dense box in index space
    glm::dmat4 index_to_world{1.0};      // the file's transform (its "world" is the medium's space)
};

// The float grid `grid` of `file`; `what` names it in budget messages ("medium \"smoke\"").
VdbDensity read_vdb_density(const std::filesystem::path& file, const std::string& grid, const std::string& what);

// The names of the grids in `file` (from its metadata, no voxels read); empty when it cannot be
// read (read_vdb_density says why, when the medium is loaded). For the pbrt importer's warning
// about a grid it does not import.
std::vector<std::string> vdb_grid_names(const std::filesystem::path& file);

}  // namespace sweeptrace
