#pragma once
// The corner-form box used across folders (BVH builder, mesh structures, the renderer's object
// bounds), in its own header so its users need not include the BVH.
#include <limits>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace collision {

// An axis-aligned box by its corners (the working form of every computed box; collision::Aabb,
// centre + size, is the thesis's shape). Default-constructed it is empty: lo = +inf, hi = -inf.
struct Bounds3 {
    glm::vec3 lo{std::numeric_limits<float>::infinity()};
    glm::vec3 hi{-std::numeric_limits<float>::infinity()};

    void extend(const glm::vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void extend(const Bounds3& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    // Halved before the sum, so huge coordinates cannot overflow lo + hi to infinity; halving is
    // exact, so elsewhere this is the same float as 0.5 (lo + hi), and it lies in [lo, hi].
    glm::vec3 center() const { return 0.5f * lo + 0.5f * hi; }
    // Half the surface area: the SAH only compares areas, so the factor 2 is dropped.
    float half_area() const {
        if (empty()) return 0.0f;
        const glm::vec3 d = hi - lo;
        return d.x * d.y + d.y * d.z + d.z * d.x;
    }
};

}  // namespace collision
