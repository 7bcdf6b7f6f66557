// The pbrt importer's transforms: each statement's matrix against one computed by hand, the split
// into our JSON's steps, the camera's pose and handedness (scene/pbrt/pbrt_world.hpp).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include <glm/matrix.hpp>

#include "pbrt_test_support.hpp"
#include "raytracer/accel/accel.hpp"
#include "raytracer/render/renderer.hpp"
#include "raytracer/scene/pbrt/pbrt_transform.hpp"
#include "raytracer/scene/scene_transform.hpp"

using namespace sweeptrace;
using sweeptrace::test::kFlipped;
using sweeptrace::test::TempDir;

namespace {

Scene load_text(const TempDir& dir, const std::string& text) {
    std::vector<std::string> warnings;
    return load_pbrt_scene(dir.write("scene.pbrt", text), false, warnings);
}

glm::dvec3 world_of(const Object& o, const glm::dvec3& p) { return glm::dvec3(o.transform.to_world * glm::vec4(glm::vec3(p), 1.0f)); }

void check_near(const glm::dvec3& a, const glm::dvec3& b, double tol = 1e-4) {
    INFO("got (" << a.x << ", " << a.y << ", " << a.z << "), expected (" << b.x << ", " << b.y << ", " << b.z << ")");
    CHECK(glm::length(a - b) <= tol);
}

}  // namespace

TEST_CASE("pbrt transforms: split into rotate, scale, rotate, translate, to double rounding", "[pbrt]") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    for (int i = 0; i < 200; ++i) {
        glm::dmat4 m(1.0);
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 3; ++r) m[c][r] = u(rng);
        if (pbrt::det3(m) < 0.0) m[0] = -m[0];
        const auto s = pbrt::split_affine(m);
        REQUIRE(s);
        glm::dvec3 a1, a2;
        double d1 = 0, d2 = 0;
        pbrt::axis_angle(s->pre_rotation, a1, d1);
        pbrt::axis_angle(s->rotation, a2, d2);
        // Rebuilt the way our loader builds a transform from the steps.
        const glm::dmat4 rebuilt = translation_matrix(s->translation) * rotation_matrix(a2, d2) * scale_matrix(s->scale) *
                                   rotation_matrix(a1, d1);
        double err = 0.0;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) err = std::max(err, std::fabs(rebuilt[c][r] - m[c][r]));
        CHECK(err < 1e-11);
    }
    glm::dmat4 mirror(1.0);
    mirror[0][0] = -1.0;
    CHECK_FALSE(pbrt::split_affine(mirror));
}

TEST_CASE("pbrt transforms: Translate, Rotate, Scale compose on the right, as pbrt does", "[pbrt]") {
    const TempDir dir;
    // T(1,2,3) R_z(90) S(2): object (1,0,0) -> (0,2,0) -> (1,4,3); (0,0,1) -> (0,0,2) -> (1,2,5).
    const Scene s = load_text(dir, std::string(kFlipped) + "WorldBegin\nTranslate 1 2 3\nRotate 90 0 0 1\nScale 2 2 2\nShape \"sphere\"\n");
    REQUIRE(s.objects.size() == 1);
    check_near(world_of(s.objects[0], {1, 0, 0}), {1, 4, 3});
    check_near(world_of(s.objects[0], {0, 0, 1}), {1, 2, 5});
}

TEST_CASE("pbrt transforms: Transform and ConcatTransform read 16 numbers column by column", "[pbrt]") {
    const TempDir dir;
    // Column-major: the last four numbers hold the translation (5, 6, 7).
    const Scene s = load_text(dir, std::string(kFlipped) +
                                       "WorldBegin\nTranslate 100 0 0\nTransform [ 0 1 0 0  -1 0 0 0  0 0 1 0  5 6 7 1 ]\n"
                                       "ConcatTransform [ 2 0 0 0  0 2 0 0  0 0 2 0  0 0 0 1 ]\nShape \"sphere\"\n");
    // x -> (0, 1, 0) after the rotation; scaled by 2 first: (1,0,0) -> (2,0,0) -> (0,2,0) + (5,6,7).
    check_near(world_of(s.objects[0], {1, 0, 0}), {5, 8, 7});
    check_near(world_of(s.objects[0], {0, 1, 0}), {3, 6, 7});
}

TEST_CASE("pbrt transforms: AttributeBegin/End, TransformBegin/End, CoordinateSystem/CoordSysTransform", "[pbrt]") {
    const TempDir dir;
    const Scene s = load_text(dir, std::string(kFlipped) +
                                       "WorldBegin\nTranslate 1 0 0\nCoordinateSystem \"a\"\n"
                                       "AttributeBegin\nTranslate 10 0 0\nShape \"sphere\"\nAttributeEnd\n"
                                       "Shape \"sphere\"\n"
                                       "TransformBegin\nTranslate 0 5 0\nTransformEnd\nShape \"sphere\"\n"
                                       "Translate 0 0 9\nCoordSysTransform \"a\"\nShape \"sphere\"\n"
                                       "Identity\nShape \"sphere\"\n");
    REQUIRE(s.objects.size() == 5);
    check_near(world_of(s.objects[0], {0, 0, 0}), {11, 0, 0});
    check_near(world_of(s.objects[1], {0, 0, 0}), {1, 0, 0});
    check_near(world_of(s.objects[2], {0, 0, 0}), {1, 0, 0});
    check_near(world_of(s.objects[3], {0, 0, 0}), {1, 0, 0});
    check_near(world_of(s.objects[4], {0, 0, 0}), {0, 0, 0});
}

TEST_CASE("pbrt transforms: ObjectInstance places the object's shapes under its own CTM", "[pbrt]") {
    const TempDir dir;
    const Scene s = load_text(dir, std::string(kFlipped) +
                                       "WorldBegin\nObjectBegin \"o\"\nTranslate 0 1 0\nShape \"sphere\"\nObjectEnd\n"
                                       "Translate 5 0 0\nObjectInstance \"o\"\nTranslate 0 0 5\nObjectInstance \"o\"\n");
    REQUIRE(s.objects.size() == 2);
    check_near(world_of(s.objects[0], {0, 0, 0}), {5, 1, 0});
    check_near(world_of(s.objects[1], {0, 0, 0}), {5, 1, 5});
}

TEST_CASE("pbrt camera: LookAt's eye and view direction, the fov on the shorter axis, the thin lens", "[pbrt]") {
    const TempDir dir;
    const Scene s = load_text(dir, std::string(kFlipped) +
                                       "LookAt 1 2 3  4 2 3  0 1 0\n"
                                       "Camera \"perspective\" \"float fov\" 30 \"float lensradius\" 0.25 \"float focaldistance\" 7\n"
                                       "Film \"rgb\" \"integer xresolution\" 40 \"integer yresolution\" 80\nWorldBegin\n");
    check_near(glm::dvec3(s.camera.position), {1, 2, 3}, 1e-6);
    check_near(glm::normalize(glm::dvec3(s.camera.look_at - s.camera.position)), {1, 0, 0}, 1e-6);
    CHECK(s.camera.aperture == 0.5f);
    CHECK(s.camera.focus_distance == 7.0f);
    // A portrait film: pbrt's 30 degrees span x; the vertical half-angle is atan(tan(15 deg) * 80 / 40).
    CHECK(s.camera.vfov_degrees == Approx(2.0 * std::atan(std::tan(15.0 * M_PI / 180.0) * 2.0) * 180.0 / M_PI).epsilon(1e-6));
    CHECK(s.film.width == 40);
    CHECK(s.film.height == 80);
}

TEST_CASE("pbrt camera: handedness: with a plain LookAt an object at +x is on the image's right, as in pbrt", "[pbrt]") {
    const TempDir dir;
    // A unit cube about the origin as a PLY file: pbrt-v4's own scenes combine plain LookAt
    // cameras with PLY meshes, which once came out mirrored.
    dir.write("cube.ply", "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
                          "element face 12\nproperty list uchar int vertex_indices\nend_header\n"
                          "-1 -1 -1\n1 -1 -1\n1 1 -1\n-1 1 -1\n-1 -1 1\n1 -1 1\n1 1 1\n-1 1 1\n"
                          "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n3 3 7 6\n3 3 6 2\n3 0 4 7\n3 0 7 3\n3 1 2 6\n3 1 6 5\n");
    // pbrt's camera space: x right, y up, z forward. Looking down +z, world +x is to the right.
    for (const char* prefix : {"", "Scale -1 1 1\n"})
        for (const char* shape : {"Shape \"sphere\" \"float radius\" 1\n", "Scale 0.8 0.8 0.8\nShape \"plymesh\" \"string filename\" \"cube.ply\"\n"}) {
            const std::string text = std::string(prefix) +
                                     "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 40\n"
                                     "Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 8\n"
                                     "Sampler \"independent\" \"integer pixelsamples\" 1\nPixelFilter \"box\"\n"
                                     "WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n"
                                     "Material \"diffuse\" \"rgb reflectance\" [0 0 0]\nTranslate 1.2 0 0\n" + shape;
            INFO("prefix '" << prefix << "', " << shape);
            // The world is pbrt's: the object stays at +x; the camera carries the handedness.
            const auto c = sweeptrace::test::convert_text(dir, text);
            CHECK(c.warnings.empty());
            CHECK(c.doc["objects"][0]["transform"].dump().find("[1.2,0.0,0.0]") != std::string::npos);
            CHECK(c.doc["camera"].value("handedness", "right") == (std::string(prefix).empty() ? "left" : "right"));
            const Scene s = load_text(dir, text);
            const auto accel = make_accel(AccelKind::Bvh, s);
            RenderOptions o;
            o.spp = 1;
            o.max_depth = 2;
            const RenderResult r = render(s, *accel, o);
            double left = 0.0, right = 0.0;  // a black object on a white sky: where it is, it is dark
            for (int y = 0; y < r.image.height; ++y)
                for (int x = 0; x < r.image.width; ++x) (x < r.image.width / 2 ? left : right) += r.image.at(x, y).g;
            INFO("left " << left << ", right " << right);
            // pbrt puts +x on the right for the plain LookAt; under `Scale -1 1 1` on the left.
            if (std::string(prefix).empty()) CHECK(right < left - 10.0);
            else CHECK(left < right - 10.0);
        }
}
