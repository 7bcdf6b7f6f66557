// The thesis's structures redone for rays (8 octants, hashed grid) must find the same nearest
// triangle as the BVH: `sweeptrace accuracy --structures` times them, this keeps them right.
#include <catch2/catch.hpp>

#include <random>

#include <glm/geometric.hpp>

#include "raytracer/accel/mesh_hashed_grid.hpp"
#include "raytracer/accel/mesh_ray_bvh.hpp"
#include "raytracer/accel/mesh_ray_octants.hpp"
#include "raytracer/accuracy/cases.hpp"

TEST_CASE("accel: octants and hashed grid hit the BVH's triangle on an icosphere", "[accel][mesh]") {
    // Level 0 has 20 large triangles, most crossing octants that hold none of their vertices
    // (where the thesis's vertex rule would lose them); level 3 has 1280 small ones.
    const int level = GENERATE(0, 3);
    const glm::vec3 centre(0.125f, -0.25f, 0.375f);
    const collision::TriangleMesh mesh = sweeptrace::accuracy::icosphere_mesh(level, centre, 1.0f);
    const sweeptrace::MeshRayBvh bvh(mesh);
    const sweeptrace::MeshRayOctants octants(mesh);
    const sweeptrace::MeshHashedGrid grid(mesh, 0.25f);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        glm::vec3 dir(u(rng), u(rng), u(rng));
        while (glm::length(dir) < 0.1f) dir = glm::vec3(u(rng), u(rng), u(rng));
        const glm::vec3 origin = centre + 3.0f * glm::normalize(dir);
        const collision::Ray ray{origin, glm::vec3(u(rng), u(rng), u(rng)) - origin};
        collision::RayHit hb, ho, hg;
        std::uint32_t tb = 0, to = 0, tg = 0;
        const bool b = bvh.intersect(ray, hb, tb);
        REQUIRE(octants.intersect(ray, ho, to) == b);
        REQUIRE(grid.intersect(ray, hg, tg) == b);
        if (!b) continue;
        ++hits;
        CHECK(to == tb);
        CHECK(tg == tb);
        CHECK(ho.t == hb.t);
    }
    CHECK(hits > 1000);  // aimed inside the unit sphere from 3 away: most rays hit
}

TEST_CASE("accel: octants over an empty mesh hit nothing", "[accel][mesh]") {
    const collision::TriangleMesh empty;
    const sweeptrace::MeshRayOctants octants(empty);
    collision::RayHit h;
    std::uint32_t t = 0;
    CHECK_FALSE(octants.intersect(collision::Ray{{0, 0, -5}, {0, 0, 1}}, h, t));
}
