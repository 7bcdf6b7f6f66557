#pragma once
// A .vdb file for tests that need one to exist (the scenes README's `vdb` example), written by
// OpenVDB in vdb_test_files.cpp so that OpenVDB's headers reach no other test file.
#include <filesystem>

namespace sweeptrace::test {

// One float grid "density", 1 at the 2 x 2 x 2 voxels of index (0, 0, 0)..(1, 1, 1), voxel size 1.
void write_small_vdb(const std::filesystem::path& file);

}  // namespace sweeptrace::test
