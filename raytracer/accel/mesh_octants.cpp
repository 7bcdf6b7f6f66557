#include "raytracer/accel/mesh_octants.hpp"

#include <utility>

#include "collision/intersect.hpp"
#include "collision/mesh_mesh.hpp"

namespace sweeptrace {

namespace {

collision::Bounds3 octant_box(const collision::Bounds3& b, const glm::vec3& mid, int i) {
    collision::Bounds3 o;
    for (int k = 0; k < 3; ++k) {
        const bool upper = (i >> k) & 1;
        o.lo[k] = upper ? mid[k] : b.lo[k];
        o.hi[k] = upper ? b.hi[k] : mid[k];
    }
    return o;
}

}  // namespace

MeshOctants::MeshOctants(const collision::TriangleMesh& mesh) : mesh_(&mesh) {
    bounds_ = collision::mesh_bounds(mesh);
    mid_ = 0.5f * (bounds_.lo + bounds_.hi);
    for (std::uint32_t t = 0; t < mesh.triangle_count(); ++t) {
        const collision::Bounds3 box = collision::triangle_bounds(mesh, t);
        // Listed by box overlap (closed intervals), so a triangle on the split plane is in both
        // halves: the thesis's vertex rule can drop a large triangle from an octant it crosses.
        for (int i = 0; i < 8; ++i) {
            if (collision::boxes_overlap(box, octant_box(bounds_, mid_, i))) octants_[i].push_back(t);
        }
    }
}

bool MeshOctants::intersect(const collision::Ray& ray, collision::RayHit& hit, std::uint32_t& triangle) const {
    const glm::vec3 inv = glm::vec3(1.0f) / ray.dir;
    std::array<std::pair<float, int>, 8> order;
    int n = 0;
    for (int i = 0; i < 8; ++i) {
        if (octants_[i].empty()) continue;
        const collision::Bounds3 o = octant_box(bounds_, mid_, i);
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
        for (std::uint32_t t : octants_[order[k].second]) {
            if (collision::intersect(r, mesh_->triangle(t), hit)) {
                r.tmax = hit.t;
                triangle = t;
                found = true;
            }
        }
    }
    return found;
}

std::size_t MeshOctants::memory_bytes() const {
    std::size_t bytes = sizeof(*this);
    for (const auto& o : octants_) bytes += o.capacity() * sizeof(std::uint32_t);
    return bytes;
}

}  // namespace sweeptrace
