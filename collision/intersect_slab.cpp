// Ray-box slab test (Kay & Kajiya), made conservative as in pbrt-v4 (Bounds3::IntersectP):
// the far distance of each slab is enlarged by 1 + 2 gamma(3) so rounding of (bound - o) * inv
// never rejects a box the exact ray meets. A zero direction component gives +-inf in inv_dir;
// (lo - o) * inf is +-inf unless lo - o == 0, where 0 * inf = NaN: the NaN comparisons below
// are arranged so that such a slab never shrinks the interval (the ray lies in the slab plane
// and is counted as inside, the conservative answer).
#include <algorithm>

#include "collision/float_error.hpp"
#include "collision/intersect.hpp"

namespace collision {

bool intersect_slab(const Ray& ray, const glm::vec3& inv_dir, const glm::vec3& lo, const glm::vec3& hi,
                    float& t_enter, float& t_exit) {
    float t0 = ray.tmin;
    float t1 = ray.tmax;
    for (int axis = 0; axis < 3; ++axis) {
        float t_near = (lo[axis] - ray.origin[axis]) * inv_dir[axis];
        float t_far = (hi[axis] - ray.origin[axis]) * inv_dir[axis];
        if (t_near > t_far) std::swap(t_near, t_far);
        t_far *= 1.0f + 2.0f * gamma(3);
        // Written so a NaN t_near / t_far leaves t0 / t1 unchanged.
        t0 = t_near > t0 ? t_near : t0;
        t1 = t_far < t1 ? t_far : t1;
        if (t0 > t1) return false;
    }
    t_enter = t0;
    t_exit = t1;
    return true;
}

}  // namespace collision
