// gzip-compressed input (scene/gzip_file.hpp), as pbrt-v4's scenes name it: a .ply.gz (or .obj.gz)
// mesh is its uncompressed mesh, a .pbrt.gz Include or main file its text; multi-member files
// inflate whole; a gzip bomb is refused at the uncompressed file's limit, and truncated, corrupt
// and non-gzip data with their one-line messages. And the pbrt importer's mapping of the JSON
// loader's complaints about an object back to the pbrt statement that wrote it (pbrt_import.cpp).
#include <catch2/catch.hpp>

#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "cli_run.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/load_budget.hpp"
#include "raytracer/scene/gzip_file.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "raytracer/scene/obj_loader.hpp"
#include "raytracer/scene/pbrt/pbrt_import.hpp"
#include "raytracer/scene/ply_loader.hpp"
#include "raytracer/scene/text_file.hpp"
#include "scene_test_files.hpp"

using namespace sweeptrace;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using sweeptrace::test::TempDir;

namespace {

// One gzip member holding `chunk` repeated `times` times, deflated as it is fed (a 100 MiB bomb
// never exists uncompressed here).
std::string gz_member(std::string_view chunk, std::size_t times = 1) {
    z_stream s{};
    if (deflateInit2(&s, Z_BEST_COMPRESSION, Z_DEFLATED, 16 + MAX_WBITS, 9, Z_DEFAULT_STRATEGY) != Z_OK)
        throw std::runtime_error("deflateInit2");
    std::string out;
    char buf[1 << 16];
    for (std::size_t i = 0; i <= times; ++i) {
        const bool last = i == times;
        s.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(chunk.data()));
        s.avail_in = last ? 0 : static_cast<uInt>(chunk.size());
        do {
            s.next_out = reinterpret_cast<Bytef*>(buf);
            s.avail_out = sizeof buf;
            if (deflate(&s, last ? Z_FINISH : Z_NO_FLUSH) == Z_STREAM_ERROR) throw std::runtime_error("deflate");
            out.append(buf, sizeof buf - s.avail_out);
        } while (s.avail_out == 0);
    }
    deflateEnd(&s);
    return out;
}

std::string gz_message(std::string_view compressed, std::uintmax_t max_bytes) {
    try {
        gunzip(compressed, "t.gz", "mesh", max_bytes);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

const std::string kGzQuadPly = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                               "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                               "0 0 0\n1 0 0\n1 1 0.25\n0 1 0\n4 0 1 2 3\n";

const std::string kGzScene = R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
  "film": {"width": 8, "height": 8, "spp": 1}, "materials": {"m": {"type": "diffuse"}},
  "objects": [{"type": "mesh", "file": "FILE", "material": "m"}]})";

std::string gz_scene_naming(const std::string& file) {
    std::string s = kGzScene;
    return s.replace(s.find("FILE"), 4, file);
}

std::string gz_slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("gzip: a .ply.gz mesh is its .ply mesh, also split into several gzip members", "[scene][gzip]") {
    const TempDir dir;
    const Mesh plain = load_ply(dir.write("quad.ply", kGzQuadPly));
    const auto gz = dir.write("quad.ply.gz", gz_member(kGzQuadPly));
    const Mesh inflated = load_ply(gz);
    CHECK(inflated.triangles.vertices == plain.triangles.vertices);
    CHECK(inflated.triangles.indices == plain.triangles.indices);
    CHECK(inflated.source == gz.string());  // the file the CLI hashes and guards is the .gz itself
    // `cat a.gz b.gz`: every member, in turn (one of them empty).
    const std::size_t half = kGzQuadPly.size() / 2;
    const Mesh members = load_ply(dir.write("members.ply.gz", gz_member(kGzQuadPly.substr(0, half)) + gz_member("") +
                                                                   gz_member(kGzQuadPly.substr(half))));
    CHECK(members.triangles.vertices == plain.triangles.vertices);
    CHECK(members.triangles.indices == plain.triangles.indices);
}

TEST_CASE("gzip: the scene loader reads NAME.ply.gz (any case) as PLY and NAME.obj.gz as OBJ", "[scene][gzip]") {
    CHECK(content_extension("a/mesh.PLY.GZ") == ".ply");
    CHECK(content_extension("mesh.ply") == ".ply");
    CHECK(content_extension("hair.pbrt.gz") == ".pbrt");
    CHECK(content_extension("archive.gz").empty());
    CHECK(is_pbrt_file("hair.pbrt.gz"));
    CHECK_FALSE(is_pbrt_file("hair.gz"));

    const TempDir dir;
    dir.write("meshes/quad.PLY.GZ", gz_member(kGzQuadPly));
    const Scene ply = load_scene(dir.write("ply.json", gz_scene_naming("meshes/quad.PLY.GZ")));
    REQUIRE(ply.meshes.size() == 1);
    CHECK(ply.meshes[0].triangles.indices.size() == 2);

    const std::string obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
    dir.write("quad.obj.gz", gz_member(obj));
    const Scene from_gz = load_scene(dir.write("obj.json", gz_scene_naming("quad.obj.gz")));
    const Mesh plain_obj = load_obj(dir.write("quad.obj", obj));
    REQUIRE(from_gz.meshes.size() == 1);
    CHECK(from_gz.meshes[0].triangles.vertices == plain_obj.triangles.vertices);
    CHECK(from_gz.meshes[0].triangles.indices == plain_obj.triangles.indices);

    // A mesh file that is not gzip, named .gz: refused at the object, naming the file.
    dir.write("fake.ply.gz", kGzQuadPly);
    try {
        load_scene(dir.write("fake.json", gz_scene_naming("fake.ply.gz")));
        FAIL("loaded a PLY that is not gzip as .ply.gz");
    } catch (const InputError& e) {
        CHECK_THAT(e.what(), Contains("objects[0].file: ") && Contains("fake.ply.gz: not a valid gzip file (incorrect header check)"));
    }
}

TEST_CASE("gzip: a .pbrt.gz Include, and a .pbrt.gz main file, are read inflated", "[scene][gzip][pbrt]") {
    const TempDir dir;
    dir.write("geometry/shapes.pbrt.gz", gz_member("Shape \"sphere\" \"float radius\" 0.5\n"
                                                   "Shape \"plymesh\" \"string filename\" \"geometry/quad.ply.gz\"\n"));
    dir.write("geometry/quad.ply.gz", gz_member(kGzQuadPly));
    const std::string text = "WorldBegin\nInclude \"geometry/shapes.pbrt.gz\"\n";
    std::vector<std::string> warnings;
    const Scene scene = load_pbrt_scene(dir.write("scene.pbrt", text), false, warnings);
    CHECK(warnings.empty());
    CHECK(scene.objects.size() == 2);
    REQUIRE(scene.meshes.size() == 1);
    CHECK(scene.meshes[0].triangles.indices.size() == 2);

    const Scene main_gz = load_pbrt_scene(dir.write("main.pbrt.gz", gz_member(text)), false, warnings);
    CHECK(main_gz.objects.size() == 2);

    // The tokenizer's checks apply to the inflated text.
    dir.write("binary.pbrt.gz", gz_member("Shape\x01\x02"));
    CHECK_THROWS_WITH(load_pbrt_scene(dir.write("inc.pbrt", "Include \"binary.pbrt.gz\"\n"), false, warnings),
                      Contains("binary.pbrt.gz:1: control byte 1"));
}

TEST_CASE("gzip: the inflated buffer is charged to the load budget while the mesh is read, and given back after", "[scene][gzip]") {
    const TempDir dir;
    const auto plain = dir.write("quad.ply", kGzQuadPly);
    const auto gz = dir.write("quad.ply.gz", gz_member(kGzQuadPly));
    const auto charged_by = [](const std::filesystem::path& file, std::optional<std::uint64_t> limit) {
        struct Limit {  // reset however the load ends
            explicit Limit(std::optional<std::uint64_t> l) { set_load_memory_limit(l); }
            ~Limit() { set_load_memory_limit(std::nullopt); }
        } set(limit);
        const LoadBudgetScope scope;
        load_ply(file);
        return load_memory_charged();
    };
    // The mesh's own charges stay; the inflated bytes (a 64 kB buffer at least) are given back.
    const std::uint64_t mesh = charged_by(plain, std::nullopt);
    CHECK(mesh > 0);
    CHECK(charged_by(gz, std::nullopt) == mesh);
    // Under a budget smaller than that first buffer, the .gz is refused and the .ply is not.
    CHECK(charged_by(plain, 60000) == mesh);
    CHECK_THROWS_WITH(charged_by(gz, 60000), Contains("quad.ply.gz: the inflated mesh (growing to 66 kB) needs 66 kB"));
}

TEST_CASE("gzip: a bomb is refused once its output passes the uncompressed file's limit", "[scene][gzip]") {
    const std::string zeros(1 << 20, '\0');
    const std::string bomb = gz_member(zeros, 100);  // 100 MiB of zeros in about 100 KB
    CHECK(bomb.size() < 200000);
    CHECK(gz_message(bomb, 1 << 20) == "t.gz: decompressed size exceeds the 1 MiB limit for a mesh");

    // A pbrt Include: its limit is kMaxSceneFileBytes (16 MiB), said at the Include.
    const TempDir dir;
    dir.write("bomb.pbrt.gz", bomb);
    std::vector<std::string> warnings;
    const auto scene = dir.write("scene.pbrt", "WorldBegin\nInclude \"bomb.pbrt.gz\"\n");
    CHECK_THROWS_WITH(load_pbrt_scene(scene, false, warnings),
                      StartsWith(scene.string() + ":2: Include: ") &&
                          Contains("bomb.pbrt.gz: decompressed size exceeds the 16 MiB limit for a pbrt scene"));

    // Exactly at the limit is fine, one byte over is not, in one member or summed over several.
    const std::string kb(1000, 'x');
    CHECK(gunzip(gz_member(kb), "t.gz", "mesh", 1000) == kb);
    CHECK_THAT(gz_message(gz_member(kb + "y"), 1000), Contains("decompressed size exceeds"));
    CHECK_THAT(gz_message(gz_member(kb.substr(0, 600)) + gz_member(kb.substr(0, 401)), 1000), Contains("decompressed size exceeds"));
    CHECK(gunzip(gz_member(kb.substr(0, 600)) + gz_member(kb.substr(0, 400)), "t.gz", "mesh", 1000) == kb);
}

TEST_CASE("gzip: truncated, corrupt and non-gzip data are refused with one line naming the file", "[scene][gzip]") {
    const std::string gz = gz_member(kGzQuadPly);
    CHECK(gz_message(gz.substr(0, gz.size() / 2), 1 << 20) == "t.gz: truncated gzip data");
    CHECK(gz_message(gz.substr(0, gz.size() - 4), 1 << 20) == "t.gz: truncated gzip data");  // no length in the trailer
    CHECK(gz_message(gz.substr(0, 5), 1 << 20) == "t.gz: truncated gzip data");                // inside the header
    CHECK(gz_message(gz + gz.substr(0, 12), 1 << 20) == "t.gz: truncated gzip data");          // a second member cut short
    CHECK(gz_message(kGzQuadPly, 1 << 20) == "t.gz: not a valid gzip file (incorrect header check)");
    CHECK(gz_message("", 1 << 20) == "t.gz: not a valid gzip file (empty file)");
    std::string bad_crc = gz;
    bad_crc[bad_crc.size() - 8] = static_cast<char>(bad_crc[bad_crc.size() - 8] ^ 1);
    CHECK(gz_message(bad_crc, 1 << 20) == "t.gz: not a valid gzip file (incorrect data check)");
    CHECK(gz_message(gz + "trailing words", 1 << 20) == "t.gz: not a valid gzip file (incorrect header check)");

    // Through a loader, the message names the file as given.
    const TempDir dir;
    const auto cut = dir.write("cut.ply.gz", gz.substr(0, gz.size() / 2));
    CHECK_THROWS_WITH(load_ply(cut), cut.string() + ": truncated gzip data");
}

TEST_CASE("pbrt: the loader's complaint about a mesh file is said at the pbrt statement that named it", "[scene][gzip][pbrt]") {
    const TempDir dir;
    dir.write("meshes/broken.ply", "PLY\nformat ascii 1.0\nend_header\n");
    dir.write("meshes/cut.ply.gz", gz_member(kGzQuadPly).substr(0, 20));
    const std::string head = "WorldBegin\nShape \"sphere\"\n";
    std::vector<std::string> warnings;
    {
        const auto scene = dir.write("scene.pbrt", head + "Shape \"plymesh\" \"string filename\" \"meshes/broken.ply\"\n");
        CHECK_THROWS_WITH(load_pbrt_scene(scene, false, warnings),
                          StartsWith(scene.string() + ":3: Shape \"plymesh\": ") && Contains("broken.ply: header line 1: not a PLY file") &&
                              !Contains("objects["));
        // convert checks its JSON the same way before writing it: the same place.
        CHECK_THROWS_WITH(convert_pbrt(scene, dir.path() / "out.json", false, true),
                          StartsWith(scene.string() + ":3: Shape \"plymesh\": ") && !Contains("out.json"));
    }
    {
        const auto scene = dir.write("cut.pbrt", head + "\n\nShape \"plymesh\" \"string filename\" \"meshes/cut.ply.gz\"\n");
        CHECK_THROWS_WITH(load_pbrt_scene(scene, false, warnings),
                          StartsWith(scene.string() + ":5: Shape \"plymesh\": ") && Contains("cut.ply.gz: truncated gzip data"));
    }
}

TEST_CASE("gzip: sweeptrace render and convert take .ply.gz meshes and .pbrt.gz files end to end", "[scene][gzip][pbrt][cli]") {
    const TempDir dir;
    const std::string camera = "LookAt 0 0.5 -3  0.5 0.5 0  0 1 0\nCamera \"perspective\" \"float fov\" 40\n"
                               "Film \"rgb\" \"integer xresolution\" 12 \"integer yresolution\" 10\n"
                               "Sampler \"independent\" \"integer pixelsamples\" 2\nWorldBegin\n"
                               "LightSource \"infinite\" \"rgb L\" [0.5 0.5 0.5]\n";
    const std::string shapes = "Shape \"plymesh\" \"string filename\" \"MESH\"\n";
    auto naming = [&](const std::string& mesh) {
        std::string s = shapes;
        return s.replace(s.find("MESH"), 4, mesh);
    };
    dir.write("plain.pbrt", camera + naming("quad.ply"));
    dir.write("quad.ply", kGzQuadPly);
    dir.write("gz.pbrt", camera + "Include \"shapes.pbrt.gz\"\n");
    dir.write("shapes.pbrt.gz", gz_member(naming("quad.ply.gz")));
    dir.write("quad.ply.gz", gz_member(kGzQuadPly));
    dir.write("whole.pbrt.gz", gz_member(camera + naming("quad.ply.gz")));
    for (const char* args : {"render plain.pbrt -o plain.pfm --quiet --threads 1", "render gz.pbrt -o gz.pfm --quiet --threads 1",
                             "render whole.pbrt.gz -o whole.pfm --quiet --threads 1", "convert whole.pbrt.gz --quiet"}) {
        const test::CliRun r = test::run_sweeptrace(dir.path(), args);
        INFO(args << ": " << r.err);
        CHECK(r.exit_code == 0);
    }
    const std::string plain = gz_slurp(dir.path() / "plain.pfm");
    CHECK(plain.size() > 12 * 10 * 12);
    CHECK(gz_slurp(dir.path() / "gz.pfm") == plain);
    CHECK(gz_slurp(dir.path() / "whole.pfm") == plain);
    CHECK(gz_slurp(dir.path() / "whole.json").find("\"quad.ply.gz\"") != std::string::npos);  // x.pbrt.gz -> x.json
}
