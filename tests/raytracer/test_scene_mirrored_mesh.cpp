// A mesh object's transform may mirror ({"scale": [-1, 1, 1]}, scene/load_scene.cpp): the mesh
// is drawn mirrored, and each face keeps its file's front, carried by the inverse transpose (as
// pbrt-v4 keeps it under a transform that swaps handedness). Checked against the same mesh
// mirrored in its file (x negated, each face's winding turned so its front is the mirror of the
// original's): every ray meets both at the same t with the same normal, on both backends, and as
// a one-sided emitter both light the same side. Other shapes still refuse a mirror.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "raytracer/accel/accel.hpp"
#include "raytracer/render/sampling/random.hpp"
#include "raytracer/render/renderer.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "scene_load_error.hpp"
#include "scene_test_files.hpp"

using namespace sweeptrace;
using sweeptrace::test::TempDir;

namespace {

// An asymmetric closed tetrahedron (faces outward) and a loose triangle beside it.
const float kVerts[5][3] = {{0.0f, 0.0f, 0.0f}, {1.2f, 0.1f, 0.0f}, {0.2f, 0.9f, 0.1f}, {0.3f, 0.2f, 0.8f}, {-0.6f, 0.5f, 0.4f}};
const int kFaces[5][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 4, 2}};

enum class Copy { Original, Mirrored, InsideOut };

// The OBJ text. Mirrored: x negated and each face's b and c swapped, so each front is the mirror
// of the original's. InsideOut: x negated only, so each front faces the other way.
std::string obj_text(Copy copy) {
    const bool negate = copy != Copy::Original, swap = copy == Copy::Mirrored;
    std::string s;
    for (const auto& v : kVerts)
        s += "v " + std::to_string(negate ? -v[0] : v[0]) + " " + std::to_string(v[1]) + " " + std::to_string(v[2]) + "\n";
    for (const auto& f : kFaces) {
        const int b = swap ? f[2] : f[1], c = swap ? f[1] : f[2];
        s += "f " + std::to_string(f[0] + 1) + " " + std::to_string(b + 1) + " " + std::to_string(c + 1) + "\n";
    }
    return s;
}

// A scene with the mesh lit from above, or itself a one-sided emitter.
std::string scene_text(const std::string& file, const std::string& mirror_step, bool emits) {
    const std::string material = emits ? R"({"type": "diffuse", "albedo": [0, 0, 0], "emission": [4, 4, 4]})" : R"({"type": "diffuse"})";
    return R"({"camera": {"position": [0.3, 1.5, 4], "look_at": [0, 0.4, 0], "fov": 35},
               "film": {"width": 24, "height": 16, "spp": 8, "max_depth": 3},
               "background": {"color": [0.2, 0.2, 0.2]},
               "materials": {"m": )" + material + R"(, "floor": {"type": "diffuse", "albedo": [0.8, 0.8, 0.8]}},
               "objects": [
                 {"type": "quad", "corner": [-3, -0.5, 3], "edge_u": [6, 0, 0], "edge_v": [0, 0, -6], "material": "floor"},
                 {"type": "mesh", "file": ")" + file + R"(", "material": "m", "transform": [)" + mirror_step +
           R"({"rotate": {"axis": [0.3, 1, 0.2], "degrees": 35}}, {"scale": [1.1, 0.9, 1.2]}, {"translate": [0.2, -0.1, 0.3]}]}]})";
}

}  // namespace

TEST_CASE("mirrored mesh: {scale: [-1, 1, 1]} is the mesh mirrored in its file, hit for hit, on both backends", "[scene][transform]") {
    const TempDir dir;
    dir.write("m.obj", obj_text(Copy::Original));
    dir.write("mirrored.obj", obj_text(Copy::Mirrored));
    const Scene a = load_scene(dir.write("a.json", scene_text("m.obj", R"({"scale": [-1, 1, 1]}, )", false)));
    const Scene b = load_scene(dir.write("b.json", scene_text("mirrored.obj", "", false)));
    for (const AccelKind kind : {AccelKind::Bvh, AccelKind::Embree}) {
        const auto accel_a = make_accel(kind, a), accel_b = make_accel(kind, b);
        Rng rng(5, 0, 0);
        int hits = 0;
        for (int i = 0; i < 4000; ++i) {
            collision::Ray ray;
            ray.origin = glm::vec3(rng.uniform() * 6.0f - 3.0f, rng.uniform() * 3.0f + 1.0f, rng.uniform() * 6.0f - 3.0f);
            const glm::vec3 target(rng.uniform() * 2.0f - 1.2f, rng.uniform() * 1.2f - 0.2f, rng.uniform() * 2.0f - 0.7f);
            ray.dir = glm::normalize(target - ray.origin);
            SurfaceHit ha, hb;
            const bool ia = accel_a->intersect(ray, ha), ib = accel_b->intersect(ray, hb);
            INFO("backend " << (kind == AccelKind::Bvh ? "bvh" : "embree") << ", ray " << i);
            REQUIRE(ia == ib);
            if (!ia) continue;
            // A ray grazing an edge may meet the neighbouring face in the other float rounding.
            if (std::fabs(ha.t - hb.t) > 1e-4f * ha.t) continue;
            hits += ha.object == hb.object && ha.object == 1;
            CHECK(ha.object == hb.object);
            CHECK(glm::length(ha.normal - hb.normal) < 1e-4f);
            CHECK(glm::length(ha.shading_normal - hb.shading_normal) < 1e-4f);
        }
        CHECK(hits > 500);  // the mesh, not only the floor, was met
    }
}

TEST_CASE("mirrored mesh: a one-sided emitting mesh lights what its mirror in the file lights", "[scene][transform]") {
    const TempDir dir;
    dir.write("m.obj", obj_text(Copy::Original));
    dir.write("mirrored.obj", obj_text(Copy::Mirrored));
    const Scene a = load_scene(dir.write("a.json", scene_text("m.obj", R"({"scale": [-1, 1, 1]}, )", true)));
    const Scene b = load_scene(dir.write("b.json", scene_text("mirrored.obj", "", true)));
    // Turned inside out, the closed tetrahedron lights nothing outside it: this test tells the sides apart.
    dir.write("inside_out.obj", obj_text(Copy::InsideOut));
    const Scene inside_out = load_scene(dir.write("c.json", scene_text("inside_out.obj", "", true)));
    RenderOptions o;
    o.spp = 64;
    o.max_depth = 3;
    o.threads = 2;
    auto mean = [&](const Scene& s) {
        const auto accel = make_accel(AccelKind::Bvh, s);
        const RenderResult r = render(s, *accel, o);
        double sum = 0.0;
        for (const glm::vec3& p : r.image.pixels) sum += p.r + p.g + p.b;
        return sum / r.image.pixels.size();
    };
    const double ma = mean(a), mb = mean(b);
    INFO("mirrored by the transform " << ma << ", mirrored in the file " << mb);
    CHECK(std::fabs(ma - mb) < 0.02 * mb);
    const double mc = mean(inside_out);
    INFO("inside out " << mc);
    CHECK(std::fabs(mc - mb) > 0.2 * mb);
}

TEST_CASE("mirrored mesh: other shapes and moving meshes still refuse a mirror", "[scene][transform][errors]") {
    const TempDir dir;
    dir.write("m.obj", obj_text(Copy::Original));
    const std::string base = R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}, "film": {"width": 8, "height": 8, "spp": 1},
                                  "materials": {"m": {"type": "diffuse"}}, "objects": [)";
    CHECK_THAT(sweeptrace::test::load_error(dir, base + R"({"type": "quad", "corner": [0, 0, 0], "edge_u": [1, 0, 0], "edge_v": [0, 1, 0],
                                                   "material": "m", "transform": [{"scale": [-1, 1, 1]}]}]})"),
               Catch::Contains("objects[0].transform[0].scale[0]: must be > 0: only a mesh's transform may mirror"));
    CHECK_THAT(sweeptrace::test::load_error(dir, base + R"({"type": "mesh", "file": "m.obj", "material": "m", "transform": [{"scale": -1}],
                                                   "motion": {"close": [{"translate": [1, 0, 0]}]}}]})"),
               Catch::Contains("objects[0].motion: a moving object's transform must not mirror"));
}
