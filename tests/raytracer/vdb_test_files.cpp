#include "vdb_test_files.hpp"

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

namespace sweeptrace::test {

void write_small_vdb(const std::filesystem::path& file) {
    openvdb::initialize();
    openvdb::FloatGrid::Ptr g = openvdb::FloatGrid::create(0.0f);
    g->setName("density");
    g->fill(openvdb::CoordBBox(openvdb::Coord(0, 0, 0), openvdb::Coord(1, 1, 1)), 1.0f);
    openvdb::io::File f(file.string());
    f.write(openvdb::GridCPtrVec{g});
    f.close();
}

}  // namespace sweeptrace::test
