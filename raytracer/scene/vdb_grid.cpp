#include "raytracer/scene/vdb_grid.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>
// NanoVDB's reader inflates zip-compressed grids with zlib (linked already for .gz meshes);
// Blosc-compressed .nvdb files are refused with NanoVDB's own reason.
#define NANOVDB_USE_ZIP 1
#include <nanovdb/util/IO.h>

#include "raytracer/input_error.hpp"
#include "raytracer/load_budget.hpp"
#include "raytracer/scene/read_files.hpp"

namespace sweeptrace {

namespace {

// Largest dense axis: the `grid` medium's own (scene/load_media.cpp), so that a sample's index
// stays exact in the float lookup.
constexpr std::int64_t kMaxAxis = std::int64_t{1} << 24;

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& message) {
    throw InputError(file.string() + ": " + message);
}

std::string quoted(const std::string& s) { return "\"" + excerpt(s) + "\""; }

// The dense box [lo, hi] (index coordinates, inclusive): its size checked and charged to the
// budget before anything is allocated.
void size_dense(VdbDensity& out, const std::array<std::int64_t, 3>& lo, const std::array<std::int64_t, 3>& hi,
                const std::filesystem::path& file, const std::string& grid, const std::string& what) {
    std::array<std::int64_t, 3> n{};
    for (int a = 0; a < 3; ++a) n[a] = hi[a] - lo[a] + 1;
    const std::string dims = std::to_string(n[0]) + " x " + std::to_string(n[1]) + " x " + std::to_string(n[2]);
    const double bytes = double(n[0]) * double(n[1]) * double(n[2]) * double(sizeof(float));
    for (int a = 0; a < 3; ++a)
        if (n[a] < 1 || n[a] > kMaxAxis)
            fail(file, "grid " + quoted(grid) + "'s active box is " + dims + " voxels; each side must be at most " +
                           std::to_string(kMaxAxis));
    // Under the 2^72 bytes of three 2^24 axes, a double holds the product; past 2^64 bytes the
    // charge is refused anyway, at its largest figure.
    const auto charge = bytes < 1.8e19 ? static_cast<std::uint64_t>(bytes) : std::numeric_limits<std::uint64_t>::max();
    charge_load_memory(charge, file.string(), what + "'s grid " + quoted(grid) + " (its active box, " + dims + " voxels, dense)");
    out.nx = static_cast<int>(n[0]);
    out.ny = static_cast<int>(n[1]);
    out.nz = static_cast<int>(n[2]);
    for (int a = 0; a < 3; ++a) {
        out.p0[a] = static_cast<float>(lo[a]) - 0.5f;
        out.p1[a] = static_cast<float>(hi[a]) + 0.5f;
    }
    out.density.resize(static_cast<std::size_t>(n[0]) * static_cast<std::size_t>(n[1]) * static_cast<std::size_t>(n[2]));
}

// Every voxel a density: >= 0 and finite (the first one that is not, by its index coordinate).
void check_values(const VdbDensity& d, const std::array<std::int64_t, 3>& lo, const std::filesystem::path& file,
                  const std::string& grid) {
    for (std::size_t i = 0; i < d.density.size(); ++i) {
        const float v = d.density[i];
        if (v >= 0.0f && std::isfinite(v)) continue;
        const std::size_t x = i % std::size_t(d.nx), y = i / std::size_t(d.nx) % std::size_t(d.ny),
                          z = i / (std::size_t(d.nx) * std::size_t(d.ny));
        fail(file, "grid " + quoted(grid) + "'s voxel (" + std::to_string(lo[0] + std::int64_t(x)) + ", " +
                       std::to_string(lo[1] + std::int64_t(y)) + ", " + std::to_string(lo[2] + std::int64_t(z)) +
                       ") is " + std::to_string(v) + "; a density must be >= 0 and finite");
    }
}

void check_background(float background, const std::filesystem::path& file, const std::string& grid) {
    if (background != 0.0f)
        fail(file, "grid " + quoted(grid) + "'s background value is " + std::to_string(background) +
                       ", not 0: a density outside its active voxels is not supported");
}

// OpenVDB trusts the sizes in a file: cut short, it reads garbage counts and may allocate
// gigabytes or read past the end. So before it opens the file, the layout is walked here (the
// header, the file's metadata, each grid's descriptor) and every grid must lie inside the file:
// a truncated file is refused by its figures. Versions before 218 (OpenVDB 2.0, 2013) have an
// older header; they are left to OpenVDB.
class LayoutReader {
public:
    explicit LayoutReader(const std::filesystem::path& file) : file_(file), in_(file, std::ios::binary) {
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
        fail(file_, std::string("truncated or corrupt: the file (") + std::to_string(size_) + " bytes) ends inside its " + what);
    }

private:
    const std::filesystem::path& file_;
    std::ifstream in_;
    std::int64_t size_ = 0;
};

void check_openvdb_layout(const std::filesystem::path& file) {
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
            fail(file, "corrupt: grid " + quoted(name) + "'s descriptor gives positions out of order");
        if (end > r.size())
            fail(file, "truncated: grid " + quoted(name) + " ends at byte " + std::to_string(end) + ", the file has " +
                           std::to_string(r.size()));
        r.seek(end);
    }
}

VdbDensity read_openvdb(const std::filesystem::path& file, const std::string& grid, const std::string& what) {
    check_openvdb_layout(file);
    openvdb::initialize();  // registers the grid and map types; idempotent
    openvdb::io::File f(file.string());
    f.open(false);  // no delayed loading: grids are read whole, when asked for, after the checks
    if (!f.hasGrid(grid)) {
        std::string names;
        for (auto it = f.beginName(); it != f.endName(); ++it) names += (names.empty() ? "" : ", ") + quoted(*it);
        fail(file, "no grid named " + quoted(grid) + " (the file holds: " + (names.empty() ? "no grids" : names) + ")");
    }
    const openvdb::GridBase::Ptr meta = f.readGridMetadata(grid);
    if (meta->valueType() != "float")
        fail(file, "grid " + quoted(grid) + " holds " + excerpt(meta->valueType()) + " values; a density grid holds float");
    const auto lo_meta = meta->getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MIN);
    const auto hi_meta = meta->getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MAX);
    const auto count = meta->getMetadata<openvdb::Int64Metadata>(openvdb::GridBase::META_FILE_VOXEL_COUNT);
    const auto mem = meta->getMetadata<openvdb::Int64Metadata>(openvdb::GridBase::META_FILE_MEM_BYTES);
    if (!lo_meta || !hi_meta || !count || !mem)
        fail(file, "grid " + quoted(grid) + " has no file_bbox_min, file_bbox_max, file_voxel_count and file_mem_bytes "
                   "metadata (OpenVDB writes them), so its size is unknown before its voxels are read");
    if (count->value() <= 0) fail(file, "grid " + quoted(grid) + " has no active voxels");
    if (!meta->transform().isLinear())
        fail(file, "grid " + quoted(grid) + " has a non-affine (frustum) transform; only affine index-to-world maps are supported");
    const openvdb::Vec3i l = lo_meta->value(), h = hi_meta->value();
    const std::array<std::int64_t, 3> lo{l.x(), l.y(), l.z()}, hi{h.x(), h.y(), h.z()};
    VdbDensity out;
    // The sparse tree as the file says it takes in memory, then the dense copy.
    charge_load_memory(static_cast<std::uint64_t>(std::max<std::int64_t>(mem->value(), 0)), file.string(),
                       what + "'s grid " + quoted(grid) + " (its sparse tree)");
    size_dense(out, lo, hi, file, grid, what);
    const openvdb::math::Mat4d m = meta->transform().baseMap()->getAffineMap()->getMat4();
    // OpenVDB multiplies row vectors (p' = p M); glm column vectors: the same matrix, transposed.
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) out.index_to_world[c][r] = m(c, r);
    const openvdb::FloatGrid::Ptr g = openvdb::gridPtrCast<openvdb::FloatGrid>(f.readGrid(grid));
    if (!g) fail(file, "grid " + quoted(grid) + " is not a float grid");
    check_background(g->background(), file, grid);
    const openvdb::CoordBBox box(openvdb::Coord(l.x(), l.y(), l.z()), openvdb::Coord(h.x(), h.y(), h.z()));
    openvdb::tools::Dense<float, openvdb::tools::LayoutXYZ> dense(box, out.density.data());
    openvdb::tools::copyToDense(*g, dense, /*serial=*/true);
    check_values(out, lo, file, grid);
    return out;
}

VdbDensity read_nanovdb(const std::filesystem::path& file, const std::string& grid, const std::string& what) {
    const std::vector<nanovdb::io::GridMetaData> metas = nanovdb::io::readGridMetaData(file.string());
    const nanovdb::io::GridMetaData* meta = nullptr;
    std::string names;
    for (const auto& m : metas) {
        names += (names.empty() ? "" : ", ") + quoted(m.gridName);
        if (m.gridName == grid && !meta) meta = &m;
    }
    if (!meta) fail(file, "no grid named " + quoted(grid) + " (the file holds: " + (names.empty() ? "no grids" : names) + ")");
    if (meta->gridType != nanovdb::GridType::Float)
        fail(file, "grid " + quoted(grid) + " holds " + nanovdb::toStr(meta->gridType) + " values; a density grid holds float");
    if (meta->voxelCount == 0) fail(file, "grid " + quoted(grid) + " has no active voxels");
    const nanovdb::Coord l = meta->indexBBox.min(), h = meta->indexBBox.max();
    const std::array<std::int64_t, 3> lo{l[0], l[1], l[2]}, hi{h[0], h[1], h[2]};
    VdbDensity out;
    charge_load_memory(meta->gridSize, file.string(), what + "'s grid " + quoted(grid) + " (its NanoVDB buffer)");
    size_dense(out, lo, hi, file, grid, what);
    const nanovdb::GridHandle<nanovdb::HostBuffer> handle = nanovdb::io::readGrid<nanovdb::HostBuffer>(file.string(), grid);
    const nanovdb::NanoGrid<float>* g = handle.grid<float>();
    if (!g) fail(file, "grid " + quoted(grid) + " is not a float grid");
    check_background(g->tree().background(), file, grid);
    // NanoVDB's map: world = M index + t, M row-major.
    const nanovdb::Map& map = g->map();
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) out.index_to_world[c][r] = map.mMatD[3 * r + c];
        out.index_to_world[3][r] = map.mVecD[r];
    }
    const auto acc = g->getAccessor();
    std::size_t i = 0;
    for (std::int64_t z = lo[2]; z <= hi[2]; ++z)
        for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
            for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
                out.density[i++] = acc.getValue(nanovdb::Coord(int(x), int(y), int(z)));
    check_values(out, lo, file, grid);
    return out;
}

enum class VdbFormat { OpenVdb, NanoVdb, Neither };

// By the magic numbers: OpenVDB's 32-bit 0x56444220 (" BDV" in the file) and NanoVDB's 64-bit
// "NanoVDB0" (both little-endian, as both libraries write them).
VdbFormat sniff(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    char head[8] = {};
    in.read(head, sizeof head);
    const auto got = in.gcount();
    if (got >= 4 && std::memcmp(head, " BDV", 4) == 0) return VdbFormat::OpenVdb;
    if (got >= 8 && std::memcmp(head, "NanoVDB0", 8) == 0) return VdbFormat::NanoVdb;
    return VdbFormat::Neither;
}

}  // namespace

VdbDensity read_vdb_density(const std::filesystem::path& file, const std::string& grid, const std::string& what) {
    if (const std::string problem = file_kind_problem(file); !problem.empty()) fail(file, problem);
    note_read_file(file);
    const VdbFormat format = sniff(file);
    if (format == VdbFormat::Neither) fail(file, "not an OpenVDB (.vdb) or NanoVDB (.nvdb) file (its first bytes are neither's magic number)");
    VdbDensity out;
    try {
        out = format == VdbFormat::OpenVdb ? read_openvdb(file, grid, what) : read_nanovdb(file, grid, what);
    } catch (const InputError&) {
        throw;
    } catch (const openvdb::Exception& e) {
        fail(file, std::string("OpenVDB cannot read it: ") + e.what());
    } catch (const std::bad_alloc&) {
        // The budget took what the file's metadata declares before any voxel was read, so this
        // is a size read from corrupt data.
        fail(file, "corrupt: reading it asked for more memory than its metadata declares");
    } catch (const std::exception& e) {
        fail(file, std::string(format == VdbFormat::OpenVdb ? "OpenVDB" : "NanoVDB") + " cannot read it: " + e.what());
    }
    return out;
}

std::vector<std::string> vdb_grid_names(const std::filesystem::path& file) {
    std::vector<std::string> names;
    if (!file_kind_problem(file).empty()) return names;
    try {
        switch (sniff(file)) {
            case VdbFormat::OpenVdb: {
                check_openvdb_layout(file);
                openvdb::initialize();
                openvdb::io::File f(file.string());
                f.open(false);
                for (auto it = f.beginName(); it != f.endName(); ++it) names.push_back(*it);
                break;
            }
            case VdbFormat::NanoVdb:
                for (const auto& m : nanovdb::io::readGridMetaData(file.string())) names.push_back(m.gridName);
                break;
            case VdbFormat::Neither: break;
        }
    } catch (const std::exception&) {
        names.clear();  // read_vdb_density reports it
    }
    return names;
}

}  // namespace sweeptrace
