// The VDB reader module (sweeptrace-vdb.so; vdb_module_abi.hpp is its whole interface): an OpenVDB
// or NanoVDB float grid's active box read into the dense buffer the executable hands it. The only
// file that includes OpenVDB and NanoVDB (tools/check_include_rules.py), built as a module of its
// own so that a process pays for loading libopenvdb and its dependencies only when a scene has a
// `vdb` medium (docs/media.md, "VDB density grids"). It links nothing of raytracer/: what it
// needs from the executable (the load budget, the dense buffer) comes through the sink.
//
// Inside, a failure is thrown (Failure: the reason; Refused: the sink said no) and caught at the
// two entry points, with the libraries' own exceptions: none leaves the module.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <exception>
#include <fstream>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>
// NanoVDB's reader inflates zip-compressed grids with zlib; Blosc-compressed .nvdb files are
// refused with NanoVDB's own reason.
#define NANOVDB_USE_ZIP 1
#include <nanovdb/util/IO.h>

#include "raytracer/input_error.hpp"
#include "raytracer/scene/vdb_module_abi.hpp"

namespace sweeptrace {

namespace {

struct Failure {
    std::string reason;
};
struct Refused {};

[[noreturn]] void fail(const std::string& reason) { throw Failure{reason}; }

std::string quoted(const std::string& s) { return "\"" + excerpt(s) + "\""; }

void charge(const SweeptraceVdbSink& sink, std::uint64_t bytes, const std::string& what) {
    if (sink.charge(sink.context, bytes, what.c_str()) != 0) throw Refused{};
}

float* dense(const SweeptraceVdbSink& sink, const std::array<std::int64_t, 3>& lo, const std::array<std::int64_t, 3>& hi) {
    float* buffer = sink.dense(sink.context, lo.data(), hi.data());
    if (!buffer) throw Refused{};
    return buffer;
}

void check_background(float background, const std::string& grid) {
    if (background != 0.0f)
        fail("grid " + quoted(grid) + "'s background value is " + std::to_string(background) +
             ", not 0: a density outside its active voxels is not supported");
}

// OpenVDB trusts the sizes in a file: cut short, it reads garbage counts and may allocate
// gigabytes or read past the end. So before it opens the file, the layout is walked here (the
// header, the file's metadata, each grid's descriptor) and every grid must lie inside the file:
// a truncated file is refused by its figures. Versions before 218 (OpenVDB 2.0, 2013) have an
// older header; they are left to OpenVDB.
class LayoutReader {
public:
    explicit LayoutReader(const char* file) : in_(file, std::ios::binary) {
        in_.seekg(0, std::ios::end);
        size_ = static_cast<std::int64_t>(in_.tellg());
        in_.seekg(0);
    }
    std::int64_t size() const { return size_; }
    std::int64_t pos() { return static_cast<std::int64_t>(in_.tellg()); }
    template <class T>
    T number(const char* what) {
        T v{};
        if (!in_.read(reinterpret_cast<char*>(&v), sizeof v)) truncated(what);
        return v;
    }
    void skip(std::int64_t bytes, const char* what) {
        if (bytes < 0 || bytes > size_ - pos()) truncated(what);
        in_.seekg(bytes, std::ios::cur);
    }
    std::string text(const char* what) {
        const auto n = number<std::int32_t>(what);
        if (n < 0 || n > size_ - pos()) truncated(what);
        std::string s(static_cast<std::size_t>(n), '\0');
        in_.read(s.data(), n);
        return s;
    }
    void seek(std::int64_t to) { in_.seekg(to); }
    [[noreturn]] void truncated(const char* what) {
        fail(std::string("truncated or corrupt: the file (") + std::to_string(size_) + " bytes) ends inside its " + what);
    }

private:
    std::ifstream in_;
    std::int64_t size_ = 0;
};

void check_openvdb_layout(const char* file) {
    LayoutReader r(file);
    r.number<std::int64_t>("header");  // the magic number, sniffed already
    const auto version = r.number<std::uint32_t>("header");
    if (version < 218) return;
    r.skip(2 * sizeof(std::uint32_t), "header");  // the library's version
    const auto offsets = r.number<char>("header");
    r.skip(36, "header");  // the file's UUID
    const auto entries = r.number<std::int32_t>("metadata");
    for (std::int32_t i = 0; i < entries; ++i) {
        r.text("metadata");
        r.text("metadata");
        r.skip(r.number<std::int32_t>("metadata"), "metadata");
    }
    if (!offsets) return;  // grids without their positions: OpenVDB streams them one by one
    const auto grids = r.number<std::int32_t>("grid count");
    for (std::int32_t i = 0; i < grids; ++i) {
        const std::string name = r.text("grid descriptors");
        r.text("grid descriptors");  // its type
        r.text("grid descriptors");  // an instance's parent
        const auto grid = r.number<std::int64_t>("grid descriptors"), block = r.number<std::int64_t>("grid descriptors"),
                   end = r.number<std::int64_t>("grid descriptors");
        if (!(r.pos() <= grid && grid <= block && block <= end))
            fail("corrupt: grid " + quoted(name) + "'s descriptor gives positions out of order");
        if (end > r.size())
            fail("truncated: grid " + quoted(name) + " ends at byte " + std::to_string(end) + ", the file has " +
                 std::to_string(r.size()));
        r.seek(end);
    }
}

// The file opened for reading its metadata and grids, after its layout is checked.
std::unique_ptr<openvdb::io::File> open_openvdb(const char* file) {
    check_openvdb_layout(file);
    openvdb::initialize();  // registers the grid and map types; idempotent
    auto f = std::make_unique<openvdb::io::File>(file);
    f->open(false);  // no delayed loading: grids are read whole, when asked for, after the checks
    return f;
}

void read_openvdb(const char* file, const std::string& grid, const SweeptraceVdbSink& sink, double index_to_world[16]) {
    const std::unique_ptr<openvdb::io::File> f = open_openvdb(file);
    if (!f->hasGrid(grid)) {
        std::string names;
        for (auto it = f->beginName(); it != f->endName(); ++it) names += (names.empty() ? "" : ", ") + quoted(*it);
        fail("no grid named " + quoted(grid) + " (the file holds: " + (names.empty() ? "no grids" : names) + ")");
    }
    const openvdb::GridBase::Ptr meta = f->readGridMetadata(grid);
    if (meta->valueType() != "float")
        fail("grid " + quoted(grid) + " holds " + excerpt(meta->valueType()) + " values; a density grid holds float");
    const auto lo_meta = meta->getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MIN);
    const auto hi_meta = meta->getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MAX);
    const auto count = meta->getMetadata<openvdb::Int64Metadata>(openvdb::GridBase::META_FILE_VOXEL_COUNT);
    const auto mem = meta->getMetadata<openvdb::Int64Metadata>(openvdb::GridBase::META_FILE_MEM_BYTES);
    if (!lo_meta || !hi_meta || !count || !mem)
        fail("grid " + quoted(grid) + " has no file_bbox_min, file_bbox_max, file_voxel_count and file_mem_bytes "
             "metadata (OpenVDB writes them), so its size is unknown before its voxels are read");
    if (count->value() <= 0) fail("grid " + quoted(grid) + " has no active voxels");
    if (!meta->transform().isLinear())
        fail("grid " + quoted(grid) + " has a non-affine (frustum) transform; only affine index-to-world maps are supported");
    const openvdb::Vec3i l = lo_meta->value(), h = hi_meta->value();
    // The sparse tree as the file says it takes in memory, then the dense copy.
    charge(sink, static_cast<std::uint64_t>(std::max<std::int64_t>(mem->value(), 0)), "grid " + quoted(grid) + " (its sparse tree)");
    float* const values = dense(sink, {l.x(), l.y(), l.z()}, {h.x(), h.y(), h.z()});
    const openvdb::math::Mat4d m = meta->transform().baseMap()->getAffineMap()->getMat4();
    // OpenVDB multiplies row vectors (p' = p M); column vectors: the same matrix, transposed.
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) index_to_world[4 * c + r] = m(c, r);
    const openvdb::FloatGrid::Ptr g = openvdb::gridPtrCast<openvdb::FloatGrid>(f->readGrid(grid));
    if (!g) fail("grid " + quoted(grid) + " is not a float grid");
    check_background(g->background(), grid);
    const openvdb::CoordBBox box(openvdb::Coord(l.x(), l.y(), l.z()), openvdb::Coord(h.x(), h.y(), h.z()));
    openvdb::tools::Dense<float, openvdb::tools::LayoutXYZ> target(box, values);
    openvdb::tools::copyToDense(*g, target, /*serial=*/true);
}

void read_nanovdb(const char* file, const std::string& grid, const SweeptraceVdbSink& sink, double index_to_world[16]) {
    const std::vector<nanovdb::io::GridMetaData> metas = nanovdb::io::readGridMetaData(file);
    const nanovdb::io::GridMetaData* meta = nullptr;
    std::string names;
    for (const auto& m : metas) {
        names += (names.empty() ? "" : ", ") + quoted(m.gridName);
        if (m.gridName == grid && !meta) meta = &m;
    }
    if (!meta) fail("no grid named " + quoted(grid) + " (the file holds: " + (names.empty() ? "no grids" : names) + ")");
    if (meta->gridType != nanovdb::GridType::Float)
        fail("grid " + quoted(grid) + " holds " + nanovdb::toStr(meta->gridType) + " values; a density grid holds float");
    if (meta->voxelCount == 0) fail("grid " + quoted(grid) + " has no active voxels");
    const nanovdb::Coord l = meta->indexBBox.min(), h = meta->indexBBox.max();
    charge(sink, meta->gridSize, "grid " + quoted(grid) + " (its NanoVDB buffer)");
    float* const values = dense(sink, {l[0], l[1], l[2]}, {h[0], h[1], h[2]});
    const nanovdb::GridHandle<nanovdb::HostBuffer> handle = nanovdb::io::readGrid<nanovdb::HostBuffer>(file, grid);
    const nanovdb::NanoGrid<float>* g = handle.grid<float>();
    if (!g) fail("grid " + quoted(grid) + " is not a float grid");
    check_background(g->tree().background(), grid);
    // NanoVDB's map: world = M index + t, M row-major.
    const nanovdb::Map& map = g->map();
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) index_to_world[4 * c + r] = map.mMatD[3 * r + c];
        index_to_world[4 * 3 + r] = map.mVecD[r];
    }
    for (int c = 0; c < 3; ++c) index_to_world[4 * c + 3] = 0.0;
    index_to_world[15] = 1.0;
    const auto acc = g->getAccessor();
    std::size_t i = 0;
    // In 64 bits: a box may end at the largest 32-bit coordinate.
    for (std::int64_t z = l[2]; z <= h[2]; ++z)
        for (std::int64_t y = l[1]; y <= h[1]; ++y)
            for (std::int64_t x = l[0]; x <= h[0]; ++x) values[i++] = acc.getValue(nanovdb::Coord(int(x), int(y), int(z)));
}

enum class VdbFormat { OpenVdb, NanoVdb, Neither };

// By the magic numbers: OpenVDB's 32-bit 0x56444220 (" BDV" in the file) and NanoVDB's 64-bit
// "NanoVDB0" (both little-endian, as both libraries write them).
VdbFormat sniff(const char* file) {
    std::ifstream in(file, std::ios::binary);
    char head[8] = {};
    in.read(head, sizeof head);
    const auto got = in.gcount();
    if (got >= 4 && std::memcmp(head, " BDV", 4) == 0) return VdbFormat::OpenVdb;
    if (got >= 8 && std::memcmp(head, "NanoVDB0", 8) == 0) return VdbFormat::NanoVdb;
    return VdbFormat::Neither;
}

int read_density(const char* file, const char* grid, const SweeptraceVdbSink* sink, double index_to_world[16]) noexcept {
    const VdbFormat format = sniff(file);
    const char* library = format == VdbFormat::OpenVdb ? "OpenVDB" : "NanoVDB";
    try {
        try {
            if (format == VdbFormat::Neither)
                fail("not an OpenVDB (.vdb) or NanoVDB (.nvdb) file (its first bytes are neither's magic number)");
            if (format == VdbFormat::OpenVdb) read_openvdb(file, grid, *sink, index_to_world);
            else read_nanovdb(file, grid, *sink, index_to_world);
            return 0;
        } catch (const Failure& f) {
            sink->fail(sink->context, f.reason.c_str());
        } catch (const Refused&) {
        } catch (const openvdb::Exception& e) {
            sink->fail(sink->context, (std::string("OpenVDB cannot read it: ") + e.what()).c_str());
        } catch (const std::bad_alloc&) {
            // The budget took what the file's metadata declares before any voxel was read, so
            // this is a size read from corrupt data.
            sink->fail(sink->context, "corrupt: reading it asked for more memory than its metadata declares");
        } catch (const std::exception& e) {
            sink->fail(sink->context, (std::string(library) + " cannot read it: " + e.what()).c_str());
        }
    } catch (...) {
        // Building a reason can itself run out of memory; the executable says so without one.
    }
    return 1;
}

int grid_names(const char* file, const SweeptraceVdbSink* sink) noexcept {
    try {
        switch (sniff(file)) {
            case VdbFormat::OpenVdb: {
                const std::unique_ptr<openvdb::io::File> f = open_openvdb(file);
                for (auto it = f->beginName(); it != f->endName(); ++it) sink->name(sink->context, (*it).c_str());
                return 0;
            }
            case VdbFormat::NanoVdb:
                for (const auto& m : nanovdb::io::readGridMetaData(file)) sink->name(sink->context, m.gridName.c_str());
                return 0;
            case VdbFormat::Neither: break;
        }
    } catch (...) {
        // read_density says why, when the medium is loaded.
    }
    return 1;
}

constexpr SweeptraceVdbModule kModule{kVdbModuleAbi, read_density, grid_names};

}  // namespace

}  // namespace sweeptrace

extern "C" const SweeptraceVdbModule* sweeptrace_vdb_module() {
    return &sweeptrace::kModule;
}
