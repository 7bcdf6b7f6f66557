// VDB density grids (scene/vdb_grid.hpp): our JSON's "vdb" medium and pbrt-v4's "nanovdb". The
// files are written here by OpenVDB and NanoVDB themselves, so nothing binary is committed: a
// 5 x 4 x 3 grid of distinct values at index box (-2, 3, 7)..(2, 6, 9), voxel size 0.5 and an
// offset, placed by the medium's own transform over the test ball (media_test_scenes.hpp).
//   - the loaded medium is the grid medium of the same values over the same world box: every
//     density sample, and world points map to the same grid coordinates;
//   - it renders the same as that grid medium (z-test), from a .vdb through our JSON and from
//     a .nvdb through the pbrt importer; the grid mirrored in x is told apart;
//   - a .nvdb with a "temperature" grid is imported with a warning naming what is lost.
//   - a truncated .nvdb, and one whose dense box is over the budget, are refused at the
//     MakeNamedMedium line (here: Python's openvdb writes no .nvdb for the corpus).
// And the reader as a module (scene/vdb_module.hpp): the program does not link OpenVDB, so a
// process that reads no `vdb` medium does not load it; a program without its module renders
// every scene without one, and a scene with one fails with exit 2, one line naming the module's
// path and the loader's reason, nothing written. (The tests above load their media through the
// module beside the test binary, tests/CMakeLists.txt.)
// The other bad files (missing, not a VDB, truncated .vdb, another grid name or value type, a
// box over the budget) are the bad-input corpus's (tests/bad_input/, media-vdb-*, pbrt-nanovdb-*).
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>
#include <nanovdb/util/IO.h>
#include <nanovdb/util/OpenToNanoVDB.h>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include "media_test_scenes.hpp"
#include "pbrt_test_support.hpp"
#include "raytracer/load_budget.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "raytracer/scene/pbrt/pbrt_import.hpp"
#include "scene_test_files.hpp"

using namespace sweeptrace;
using sweeptrace::test::TempDir;

namespace {

constexpr int kNx = 5, kNy = 4, kNz = 3;
const openvdb::Coord kFirst(-2, 3, 7);  // the index box's lower corner: not 0, so its offset counts

// Distinct, positive, and steep in x (so a mirrored grid renders differently).
float voxel_value(int i, int j, int k) { return 0.2f + 0.5f * float(i) + 0.15f * float(j * j) + 0.3f * float(k); }

// Index space (box [-2.5, 2.5] x [2.5, 6.5] x [6.5, 9.5]) times 0.5 plus (0.1, -0.3, 0.2) is the
// file's world; the medium's transform below takes that box to [-1.25, 1.25] x [-1, 1] x [-0.75, 0.75].
const char* const kMediumTransform = "[{\"translate\": [-0.1, -1.95, -4.2]}]";
const glm::vec3 kBoxLo(-1.25f, -1.0f, -0.75f), kBoxHi(1.25f, 1.0f, 0.75f);

openvdb::FloatGrid::Ptr density_grid(const std::string& name, float scale = 1.0f) {
    openvdb::initialize();
    openvdb::FloatGrid::Ptr g = openvdb::FloatGrid::create(0.0f);
    g->setName(name);
    for (int k = 0; k < kNz; ++k)
        for (int j = 0; j < kNy; ++j)
            for (int i = 0; i < kNx; ++i) g->tree().setValue(kFirst.offsetBy(i, j, k), scale * voxel_value(i, j, k));
    openvdb::math::Transform::Ptr xf = openvdb::math::Transform::createLinearTransform(0.5);
    xf->postTranslate(openvdb::Vec3d(0.1, -0.3, 0.2));
    g->setTransform(xf);
    return g;
}

void write_vdb(const std::filesystem::path& file, const openvdb::FloatGrid::Ptr& grid) {
    openvdb::io::File f(file.string());
    f.write(openvdb::GridCPtrVec{grid});
    f.close();
}

void write_nvdb(const std::filesystem::path& file, const std::vector<openvdb::FloatGrid::Ptr>& grids) {
    std::vector<nanovdb::GridHandle<nanovdb::HostBuffer>> handles;
    for (const auto& g : grids) handles.push_back(nanovdb::openToNanoVDB(*g));
    nanovdb::io::writeGrids(file.string(), handles);
}

// The grid medium written by hand: the same values over the same world box.
Medium reference_grid(bool mirror_x = false) {
    Medium m;
    m.kind = Medium::Kind::Grid;
    m.name = "smoke";
    m.sigma_a = glm::vec3(0.1f, 0.2f, 0.4f);
    m.sigma_s = glm::vec3(1.2f, 0.9f, 0.6f);
    m.g = 0.3f;
    m.nx = kNx;
    m.ny = kNy;
    m.nz = kNz;
    for (int k = 0; k < kNz; ++k)
        for (int j = 0; j < kNy; ++j)
            for (int i = 0; i < kNx; ++i) m.density.push_back(voxel_value(mirror_x ? kNx - 1 - i : i, j, k));
    m.p0 = kBoxLo;
    m.p1 = kBoxHi;
    return m;
}

const char* const kCoefficients = "\"sigma_a\": [0.1, 0.2, 0.4], \"sigma_s\": [1.2, 0.9, 0.6], \"g\": 0.3";

Medium load_vdb_medium(const TempDir& dir) {
    write_vdb(dir.path() / "smoke.vdb", density_grid("density"));
    const std::string scene = std::string("{\"camera\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0]},"
                                          "\"film\": {\"width\": 8, \"height\": 8, \"spp\": 1},"
                                          "\"materials\": {\"m\": {\"type\": \"interface\"}},"
                                          "\"media\": {\"smoke\": {\"type\": \"vdb\", \"file\": \"smoke.vdb\", ") +
                              kCoefficients + ", \"transform\": " + kMediumTransform + "}},"
                              "\"objects\": [{\"type\": \"sphere\", \"radius\": 1, \"material\": \"m\", \"inside\": \"smoke\"}]}";
    const Scene s = load_scene(dir.write("scene.json", scene));
    REQUIRE(s.media.size() == 1);
    return s.media[0];
}

std::string nanovdb_pbrt(const std::string& extra = "") {
    return "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\nAttributeBegin\n"
           "Translate -0.1 -1.95 -4.2\nMakeNamedMedium \"smoke\" \"string type\" \"nanovdb\" \"string filename\" \"smoke.nvdb\" "
           "\"rgb sigma_a\" [0.1 0.2 0.4] \"rgb sigma_s\" [1.2 0.9 0.6] \"float g\" 0.3" + extra +
           "\nAttributeEnd\nMediumInterface \"smoke\" \"\"\nMaterial \"interface\"\nShape \"sphere\"\n";
}

// Where the medium's grid coordinates ([0, 1]^3 over its box) of world point `w` fall.
glm::vec3 grid_coordinates(const Medium& m, const glm::vec3& w) {
    const glm::vec3 p(m.to_medium * glm::vec4(w, 1.0f));
    return (p - m.p0) / (m.p1 - m.p0);
}

void check_same_grid(const Medium& got, const Medium& want) {
    CHECK(got.kind == Medium::Kind::Grid);
    CHECK(got.nx == want.nx);
    CHECK(got.ny == want.ny);
    CHECK(got.nz == want.nz);
    CHECK(got.density == want.density);
    CHECK(got.sigma_a == want.sigma_a);
    CHECK(got.sigma_s == want.sigma_s);
    CHECK(got.g == want.g);
    for (const glm::vec3& w : {kBoxLo, kBoxHi, glm::vec3(0.3f, -0.2f, 0.1f), glm::vec3(-1.0f, 0.7f, 0.5f)}) {
        const glm::vec3 a = grid_coordinates(got, w), b = grid_coordinates(want, w);
        INFO("world (" << w.x << ", " << w.y << ", " << w.z << ")");
        for (int c = 0; c < 3; ++c) CHECK(a[c] == Approx(b[c]).margin(1e-5));
    }
}

RenderResult render_ball(const Medium& m, std::uint64_t seed) {
    return sweeptrace::testing::render_with(sweeptrace::testing::medium_ball_scene(m), AccelKind::Bvh, 96, 8, seed);
}

// What `ldd` lists for `file`: every shared library the loader maps for it at start.
std::string linked_libraries(const std::filesystem::path& file) {
    const std::string cmd = "ldd '" + file.string() + "'";
    std::FILE* pipe = popen(cmd.c_str(), "r");
    REQUIRE(pipe);
    std::string out;
    char buf[4096];
    while (const std::size_t n = std::fread(buf, 1, sizeof buf, pipe)) out.append(buf, n);
    pclose(pipe);
    return out;
}

const std::filesystem::path kModuleTestBuild = SWEEPTRACE_BINARY_DIR;

std::string vdb_module_scene(const std::string& media, const std::string& inside) {
    return "{\"camera\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0]},"
           "\"film\": {\"width\": 8, \"height\": 8, \"spp\": 1},"
           "\"materials\": {\"m\": {\"type\": \"interface\"}}, \"media\": {" + media + "},"
           "\"objects\": [{\"type\": \"sphere\", \"radius\": 1, \"material\": \"m\"" + inside + "}]}";
}

const std::string kModuleTestMedium = "\"smoke\": {\"type\": \"vdb\", \"file\": \"smoke.vdb\", \"sigma_s\": [1, 1, 1]}";

}  // namespace

TEST_CASE("media vdb: a .vdb grid loads as the grid medium of its values over its transformed box", "[media][vdb]") {
    const TempDir dir;
    check_same_grid(load_vdb_medium(dir), reference_grid());
}

TEST_CASE("media vdb: a .vdb medium renders as the equivalent grid medium, and a mirrored grid is told apart", "[media][vdb]") {
    const TempDir dir;
    const RenderResult reference = render_ball(reference_grid(), 3);
    CHECK(sweeptrace::testing::blocks_apart(reference, render_ball(load_vdb_medium(dir), 4)) == 0);
    CHECK(sweeptrace::testing::blocks_apart(reference, render_ball(reference_grid(true), 5)) > 0);
}

TEST_CASE("media vdb: pbrt-v4's nanovdb medium imports as the same grid and renders as it", "[media][vdb][pbrt]") {
    const TempDir dir;
    write_nvdb(dir.path() / "smoke.nvdb", {density_grid("density")});
    std::vector<std::string> warnings;
    const Scene s = load_pbrt_scene(dir.write("scene.pbrt", nanovdb_pbrt()), false, warnings);
    CHECK(warnings.empty());
    REQUIRE(s.media.size() == 1);
    check_same_grid(s.media[0], reference_grid());
    CHECK(sweeptrace::testing::blocks_apart(render_ball(reference_grid(), 3), render_ball(s.media[0], 6)) == 0);
}

TEST_CASE("media vdb: a nanovdb file's temperature grid is warned as lost, and another gridname is read", "[media][vdb][pbrt]") {
    const TempDir dir;
    write_nvdb(dir.path() / "smoke.nvdb", {density_grid("temperature", 100.0f), density_grid("smoky")});
    std::vector<std::string> warnings;
    const Scene s = load_pbrt_scene(dir.write("scene.pbrt", nanovdb_pbrt(" \"string gridname\" \"smoky\"")), false, warnings);
    CHECK(sweeptrace::test::has_warning(warnings, "the blackbody emission of a \"temperature\" grid is not imported"));
    REQUIRE(s.media.size() == 1);
    check_same_grid(s.media[0], reference_grid());
}

TEST_CASE("media vdb: a truncated or oversized .nvdb is refused at its MakeNamedMedium line", "[media][vdb][pbrt]") {
    const TempDir dir;
    const std::filesystem::path nvdb = dir.path() / "smoke.nvdb";
    const std::filesystem::path scene = dir.write("scene.pbrt", nanovdb_pbrt());
    std::vector<std::string> warnings;
    // Cut in its grid's buffer.
    write_nvdb(nvdb, {density_grid("density")});
    std::filesystem::resize_file(nvdb, std::filesystem::file_size(nvdb) / 2);
    CHECK_THROWS_WITH(load_pbrt_scene(scene, false, warnings),
                      Catch::Contains("scene.pbrt:6: MakeNamedMedium \"smoke\": ") && Catch::Contains("smoke.nvdb: NanoVDB cannot read it"));
    // Two voxels 3000 apart: a small file whose dense box (3001^3 floats, 108 GB) is over the budget.
    openvdb::FloatGrid::Ptr far = openvdb::FloatGrid::create(0.0f);
    far->setName("density");
    far->tree().setValue(openvdb::Coord(0, 0, 0), 1.0f);
    far->tree().setValue(openvdb::Coord(3000, 3000, 3000), 1.0f);
    write_nvdb(nvdb, {far});
    set_load_memory_limit(std::uint64_t{1} << 30);
    CHECK_THROWS_WITH(load_pbrt_scene(scene, false, warnings),
                      Catch::Contains("scene.pbrt:6: MakeNamedMedium \"smoke\": ") &&
                          Catch::Contains("(its active box, 3001 x 3001 x 3001 voxels, dense) needs 108.11 GB"));
    set_load_memory_limit(std::nullopt);
}

TEST_CASE("vdb module: sweeptrace starts without OpenVDB, which only its module loads", "[vdb][module]") {
    const std::string program = linked_libraries(kModuleTestBuild / "sweeptrace");
    INFO(program);
    CHECK(program.find("libtbb") != std::string::npos);  // ldd answered
    CHECK(program.find("libopenvdb") == std::string::npos);
    CHECK(program.find("libblosc") == std::string::npos);
    const std::string module = linked_libraries(kModuleTestBuild / "sweeptrace-vdb.so");
    INFO(module);
    CHECK(module.find("libopenvdb") != std::string::npos);
}

TEST_CASE("vdb module: without its module sweeptrace renders scenes without vdb media and refuses one with", "[vdb][module]") {
    const TempDir dir;
    const std::filesystem::path program = dir.path() / "sweeptrace";
    std::filesystem::copy_file(kModuleTestBuild / "sweeptrace", program);
    write_vdb(dir.path() / "smoke.vdb", density_grid("density"));
    dir.write("plain.json", vdb_module_scene("", ""));
    dir.write("smoke.json", vdb_module_scene(kModuleTestMedium, ", \"inside\": \"smoke\""));
    const auto run = [&](const std::string& args) {
        const std::string cmd = "cd '" + dir.path().string() + "' && ./sweeptrace " + args + " 2> stderr.txt > /dev/null";
        const int status = std::system(cmd.c_str());
        std::ifstream in(dir.path() / "stderr.txt");
        return std::make_pair(WIFEXITED(status) ? WEXITSTATUS(status) : -1,
                              std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()));
    };
    const std::string module = (dir.path() / "sweeptrace-vdb.so").string();
    SECTION("no module") {
        // A scene with a vdb medium in its table but on no object loads it all the same.
        dir.write("unused.json", vdb_module_scene(kModuleTestMedium, ""));
        CHECK(run("render plain.json -o plain.png").first == 0);
        CHECK(std::filesystem::exists(dir.path() / "plain.png"));
        for (const char* s : {"smoke", "unused"}) {
            const auto [code, err] = run(std::string("render ") + s + ".json -o out.png");
            INFO(err);
            CHECK(code == 2);
            CHECK(err.rfind("sweeptrace: error: ", 0) == 0);
            CHECK(err.find('\n') == err.size() - 1);
            CHECK(err.find("media.smoke.file: ") != std::string::npos);
            CHECK(err.find("the VDB reader module " + module + " did not load: ") != std::string::npos);
            CHECK(err.find("cannot open shared object file") != std::string::npos);
            CHECK_FALSE(std::filesystem::exists(dir.path() / "out.png"));
        }
    }
    SECTION("a module that is not one") {
        dir.write("sweeptrace-vdb.so", "not a shared object\n");
        const auto [code, err] = run("render smoke.json -o out.png");
        INFO(err);
        CHECK(code == 2);
        CHECK(err.find("the VDB reader module " + module + " did not load: ") != std::string::npos);
        CHECK_FALSE(std::filesystem::exists(dir.path() / "out.png"));
        CHECK(run("render plain.json -o plain.png").first == 0);
    }
    SECTION("the module beside it") {
        std::filesystem::copy_file(kModuleTestBuild / "sweeptrace-vdb.so", module);
        const auto [code, err] = run("render smoke.json -o out.png");
        INFO(err);
        CHECK(code == 0);
        CHECK(std::filesystem::exists(dir.path() / "out.png"));
    }
}
