// The PLY reader (scene/ply_loader.hpp): the three encodings give the same mesh, quads and
// polygons split as stated, normals and uv kept under each name PLY exporters use, unknown
// elements and properties skipped, and every malformed file refused with its byte or line.
#include <catch2/catch.hpp>

#include <bit>
#include <cstdint>
#include <cstring>
#include <string>

#include "raytracer/input_error.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "raytracer/scene/ply_loader.hpp"
#include "scene_test_files.hpp"

using namespace sweeptrace;
using Catch::Matchers::Contains;

namespace {

// Little- or big-endian bytes of a value, whatever the host's order.
template <class T>
void put(std::string& out, T value, bool big) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, &value, sizeof(T));
    if ((std::endian::native == std::endian::big) != big)
        for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    out.append(reinterpret_cast<const char*>(b), sizeof(T));
}

const float kPos[4][3] = {{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 0.25f}, {0.1f, 1.0f, -3.5e-3f}};

// A quad (split in two) with an extra vertex property and an extra face property, in `format`.
std::string quad_ply(const std::string& format) {
    std::string s = "ply\nformat " + format + " 1.0\ncomment a quad\nelement vertex 4\nproperty float x\nproperty float y\n"
                    "property float z\nproperty uchar red\nelement face 1\nproperty list uchar int vertex_indices\n"
                    "property short flags\nend_header\n";
    if (format == "ascii") {
        s += "0 0 0 9\n1 0 0 9\n1 1 0.25 9\n0.1 1 -3.5e-3 9\n4 0 1 2 3 -7\n";
        return s;
    }
    const bool big = format == "binary_big_endian";
    for (const auto& p : kPos) {
        for (float c : p) put(s, c, big);
        put<std::uint8_t>(s, 9, big);
    }
    put<std::uint8_t>(s, 4, big);
    for (std::int32_t i : {0, 1, 2, 3}) put(s, i, big);
    put<std::int16_t>(s, -7, big);
    return s;
}

std::string ascii_header(const std::string& vertex_props, int vertices, int faces) {
    return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(vertices) + "\n" + vertex_props + "element face " +
           std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n";
}
const std::string kXyz = "property float x\nproperty float y\nproperty float z\n";

}  // namespace

TEST_CASE("ply: ASCII, little- and big-endian binary give the same mesh, a quad is two triangles", "[scene][ply]") {
    const Mesh a = parse_ply(quad_ply("ascii"), "a.ply");
    REQUIRE(a.triangles.indices.size() == 2);
    CHECK(a.triangles.indices[0] == glm::uvec3(0, 1, 2));
    CHECK(a.triangles.indices[1] == glm::uvec3(0, 2, 3));
    REQUIRE(a.triangles.vertices.size() == 4);
    for (int v = 0; v < 4; ++v)
        for (int c = 0; c < 3; ++c) CHECK(a.triangles.vertices[v][c] == kPos[v][c]);  // decimal -> float exactly as the compiler's
    CHECK(a.vertex_normals.empty());
    CHECK(a.vertex_uvs.empty());
    for (const char* f : {"binary_little_endian", "binary_big_endian"}) {
        INFO(f);
        const Mesh b = parse_ply(quad_ply(f), "b.ply");
        CHECK(b.triangles.indices == a.triangles.indices);
        CHECK(b.triangles.vertices == a.triangles.vertices);
    }
}

TEST_CASE("ply: polygons are fanned, unused vertices dropped, normals made unit, uv read under each name", "[scene][ply]") {
    const std::string pentagon = ascii_header(kXyz, 6, 1) + "9 9 9\n0 0 0\n1 0 0\n2 1 0\n1 2 0\n0 1 0\n5 1 2 3 4 5\n";
    const Mesh p = parse_ply(pentagon, "p.ply");
    REQUIRE(p.triangles.indices.size() == 3);
    CHECK(p.triangles.vertices.size() == 5);  // vertex 0 is used by no face
    CHECK(p.triangles.vertices[0] == glm::vec3(0.0f));
    CHECK(p.triangles.indices[2] == glm::uvec3(0, 3, 4));

    for (const auto& [u, v] : {std::pair{"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}}) {
        INFO(u);
        const std::string props = kXyz + "property float nx\nproperty float ny\nproperty float nz\nproperty float " + u +
                                  "\nproperty float " + v + "\n";
        const Mesh m = parse_ply(ascii_header(props, 3, 1) + "0 0 0 0 0 2 0 0\n1 0 0 0 0 5 1 0\n0 1 0 0 3 4 0.5 1\n3 0 1 2\n", "n.ply");
        REQUIRE(m.vertex_normals.size() == 3);
        CHECK(m.vertex_normals[0] == glm::vec3(0, 0, 1));
        CHECK(m.vertex_normals[2] == glm::vec3(0, 0.6f, 0.8f));
        REQUIRE(m.vertex_uvs.size() == 3);
        CHECK(m.vertex_uvs[2] == glm::vec2(0.5f, 1.0f));
    }
    // A zero normal anywhere: the mesh shades flat (as the OBJ loader does).
    const std::string props = kXyz + "property float nx\nproperty float ny\nproperty float nz\n";
    const Mesh flat = parse_ply(ascii_header(props, 3, 1) + "0 0 0 0 0 1\n1 0 0 0 0 0\n0 1 0 0 0 1\n3 0 1 2\n", "f.ply");
    CHECK(flat.vertex_normals.empty());
}

TEST_CASE("ply: other elements, list properties and faces before vertices are read past correctly", "[scene][ply]") {
    // An element of no properties takes no bytes whatever its count (and no time: a fuzzer's
    // 4e9 empty records once took a minute to skip).
    std::string s = "ply\nformat binary_little_endian 1.0\nelement nothing 4000000000\nelement material 2\nproperty list uchar float weights\n"
                    "element face 1\nproperty uint tag\nproperty list uint uint vertex_index\n"
                    "element vertex 3\nproperty double x\nproperty double y\nproperty double z\nend_header\n";
    put<std::uint8_t>(s, 2, false);
    put(s, 1.0f, false);
    put(s, 2.0f, false);
    put<std::uint8_t>(s, 0, false);
    put<std::uint32_t>(s, 77, false);
    put<std::uint32_t>(s, 3, false);
    for (std::uint32_t i : {2u, 1u, 0u}) put(s, i, false);
    for (double c : {0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0}) put(s, c, false);
    const Mesh m = parse_ply(s, "m.ply");
    REQUIRE(m.triangles.indices.size() == 1);
    CHECK(m.triangles.vertices[0] == glm::vec3(0, 1, 0));  // vertex 2, first used
    CHECK(m.triangles.indices[0] == glm::uvec3(0, 1, 2));
}

TEST_CASE("ply: malformed files are refused with the byte or line, before allocating what they claim", "[scene][ply]") {
    auto fails = [](const std::string& bytes, const std::string& what) {
        INFO(bytes.substr(0, 200));
        CHECK_THROWS_WITH(parse_ply(bytes, "bad.ply"), Contains("bad.ply: ") && Contains(what));
    };
    fails("PLY\n", "header line 1: not a PLY file");
    fails("ply\nformat ascii 1.0\nelement vertex 3\n", "no end_header");
    fails("ply\nformat binary_middle_endian 1.0\nend_header\n", "header line 2: unknown format");
    fails("ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n", "header line 4: unknown type \"float128\"");
    fails("ply\nformat ascii 1.0\nelement vertex -1\nend_header\n", "header line 3: element count");
    fails(ascii_header("property float x\nproperty float y\n", 1, 0) + "0 0\n", "the vertex element needs properties x, y and z");
    fails(ascii_header(kXyz, 3, 1) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "line 13: face 0 names vertex 3, the file has 3");
    fails(ascii_header(kXyz, 3, 1) + "0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", "line 13: face 0 names vertex -1");
    fails(ascii_header(kXyz, 3, 1) + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "line 13: face 0 has 2 corners");
    fails(ascii_header(kXyz, 3, 1) + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", "line 11: vertex 1's y is not finite");
    fails(ascii_header(kXyz, 3, 1) + "0 0 0\n1 0x 0\n0 1 0\n3 0 1 2\n", "line 11: \"0x\" is not a number");
    fails(ascii_header(kXyz, 3, 1) + "0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n", "not an integer");
    fails(ascii_header(kXyz, 3, 1) + "0 0 0\n1 0 0\n0 1 0\n3 0 1\n", "the data ends early");
    fails(ascii_header(kXyz, 3, 0) + "0 0 0\n1 0 0\n0 1 0\n", "contains no faces");
    // Binary: a cut record names its byte; a count larger than the file is refused from the header.
    std::string cut = quad_ply("binary_little_endian");
    const std::size_t header = cut.find("end_header\n") + 11;
    cut.resize(header + 4 * 13 + 1 + 8);  // inside the face's corners
    fails(cut, "byte " + std::to_string(header + 4 * 13 + 1 + 8) + ": the data ends early");
    fails("ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n" + kXyz +
              "element face 1\nproperty list uchar int vertex_indices\nend_header\n",
          "header line 3: element \"vertex\" declares 4000000000 records, more than the 0 bytes");
}

TEST_CASE("ply: a scene's mesh object reads a .ply file and needs a material", "[scene][ply]") {
    sweeptrace::test::TempDir dir;
    dir.write("quad.PLY", quad_ply("binary_big_endian"));
    const std::string scene = R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}, "film": {"width": 8, "height": 8},
        "materials": {"m": {"type": "diffuse"}}, "objects": [{"type": "mesh", "file": "quad.PLY", "material": "m"}]})";
    const Scene s = load_scene(dir.write("s.json", scene));
    REQUIRE(s.meshes.size() == 1);
    CHECK(s.meshes[0].triangles.indices.size() == 2);
    const std::string no_material = R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}, "film": {"width": 8, "height": 8},
        "materials": {"m": {"type": "diffuse"}}, "objects": [{"type": "mesh", "file": "quad.PLY", "materials": "from_obj"}]})";
    CHECK_THROWS_WITH(load_scene(dir.write("t.json", no_material)), Contains("objects[0].materials: a PLY mesh has no materials"));
    dir.write("bad.ply", "ply\nformat ascii 1.0\nelement vertex 1\nend_header\n");
    const std::string bad = R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}, "film": {"width": 8, "height": 8},
        "materials": {"m": {"type": "diffuse"}}, "objects": [{"type": "mesh", "file": "bad.ply", "material": "m"}]})";
    CHECK_THROWS_WITH(load_scene(dir.write("u.json", bad)), Contains("objects[0].file") && Contains("bad.ply: header line 3"));
}
