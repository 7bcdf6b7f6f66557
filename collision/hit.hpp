#pragma once
// Results of the three families of tests.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace collision {

// Ray-shape intersection. Written only when a hit in (ray.tmin, ray.tmax) is found.
struct RayHit {
    float t = 0.0f;              // ray parameter of the nearest hit
    glm::vec3 point{0.0f};       // hit point (re-projected on the surface where the shape allows)
    glm::vec3 point_error{0.0f}; // conservative per-axis bound of |point - s| for a point s
                                 // exactly on the surface near the exact hit: the distance
                                 // to the surface, what offsetting the next ray needs (along
                                 // the surface the point is as good as t; each intersector
                                 // states both bounds)
    glm::vec3 normal{0.0f};      // unit geometric normal, pointing out of the shape (for flat
                                 // shapes: the shape's own normal); never flipped toward the ray
    glm::vec2 uv{0.0f};          // triangles: barycentrics (b1, b2) of b and c; quads: (s, t);
                                 // boxes, planes: documented per shape; curved shapes and
                                 // disks: 0, collision::surface_uv computes it on request
};

// Discrete overlap: the thesis's Data{occurred, displacement}. `displacement` is the minimal
// translation that, applied to the *first* shape, separates the two (zero when !hit).
struct Contact {
    bool hit = false;
    glm::vec3 displacement{0.0f};
};

// Swept test: first time of contact t in [0, 1] along the motion, the contact point at that time
// and the contact normal (unit, pointing from the still shape toward the moving one).
struct TimeOfImpact {
    bool hit = false;
    float t = 0.0f;
    glm::vec3 point{0.0f};
    glm::vec3 normal{0.0f};
};

}  // namespace collision
