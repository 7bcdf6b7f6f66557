#include "raytracer/accel/mesh_ray_octants.hpp"

#include <array>
#include <utility>

#include "collision/intersect.hpp"

namespace sweeptrace {

// Listed by box overlap (closed intervals), so a triangle on the split plane is in both halves:
// the thesis's vertex rule can drop a large triangle from an octant it crosses.
MeshRayOctants::MeshRayOctants(const collision::TriangleMesh& mesh)
    : octants_(collision::build_octants(mesh, collision::OctantRule::boxes)) {}

bool MeshRayOctants::intersect(const collision::Ray& ray, collision::RayHit& hit, std::uint32_t& triangle) const {
    const glm::vec3 inv = glm::vec3(1.0f) / ray.dir;
    std::array<std::pair<float, int>, 8> order;
    int n = 0;
    for (int i = 0; i < 8; ++i) {
        if (octants_.triangles[i].empty()) continue;
        const collision::Bounds3& o = octants_.octant[i];
        float t0 = 0.0f, t1 = 0.0f;
        if (collision::intersect_slab(ray, inv, o.lo, o.hi, t0, t1)) order[n++] = {t0, i};
    }
    // Insertion sort by entry distance (at most 8 entries).
    for (int i = 1; i < n; ++i) {
        for (int j = i; j > 0 && order[j].first < order[j - 1].first; --j) std::swap(order[j], order[j - 1]);
    }
    collision::Ray r = ray;
    bool found = false;
    for (int k = 0; k < n; ++k) {
        if (found && order[k].first > r.tmax) break;  // every later octant starts beyond the hit
        for (std::uint32_t t : octants_.triangles[order[k].second]) {
            if (collision::intersect(r, octants_.mesh->triangle(t), hit)) {
                r.tmax = hit.t;
                triangle = t;
                found = true;
            }
        }
    }
    return found;
}

}  // namespace sweeptrace
