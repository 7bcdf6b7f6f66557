// Thesis §3.1.5 ("bean", continuous) as a ray cast: the thesis's sphere test on both end
// spheres and its cylinder test (caps included) on the middle, the candidate nearest the start
// in (tmin, tmax) wins.
// Weaknesses kept: the parts are tested as whole solids, so a ray starting inside the capsule
// reports the nearest *interior* surface ahead of it (a cylinder cap inside an end sphere, or a
// sphere's far side inside the cylinder) instead of the capsule's exit; the cylinder test's
// inside-skip of the side (thesis/intersect_cylinder.cpp) and the textbook quadratic's
// cancellations come along. Normal and point: those of the part hit; point_error 0.
#include "collision/thesis/intersect.hpp"

namespace collision::thesis {

bool intersect(const Ray& ray, const Capsule& cap, RayHit& hit) {
    const glm::vec3 half(0.0f, 0.5f * cap.height, 0.0f);
    Ray narrowing = ray;
    bool found = false;
    RayHit part;
    const auto keep = [&](bool got) {
        if (!got) return;
        hit = part;
        narrowing.tmax = part.t;
        found = true;
    };
    keep(intersect(narrowing, Sphere{cap.center - half, cap.radius}, part));
    keep(intersect(narrowing, Sphere{cap.center + half, cap.radius}, part));
    keep(intersect(narrowing, Cylinder{cap.center, cap.radius, cap.height}, part));
    return found;
}

}  // namespace collision::thesis
