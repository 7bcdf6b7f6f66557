// Ray-triangle intersection, robust default: the watertight test (Woop, Benthin, Wald 2013).
// Method, error bounds and degenerate-input behaviour: collision/triangle_watertight.hpp.
// The thesis's plane + barycentric test is collision/thesis/intersect_triangle.cpp.
#include "collision/intersect.hpp"
#include "collision/triangle_watertight.hpp"

namespace collision {

bool intersect(const Ray& ray, const Triangle& tri, RayHit& hit) {
    const TriangleRay tr = prepare_triangle_ray(ray);
    TriangleCandidate cand;
    if (!intersect_triangle_candidate(ray, tr, tri.a, tri.b, tri.c, cand)) return false;
    finish_triangle_hit(tri.a, tri.b, tri.c, cand, hit);
    return true;
}

}  // namespace collision
