#pragma once
// Every emissive object of a scene as a light that next event estimation can sample, and the
// density with which it would have sampled a point that a BSDF-sampled ray found (for MIS).
//
// Strategies (all exact: the density used in MIS is the one sampled with); each shape's home
// (geometry/shapes/) says which one fits it and draws its surface points:
// - SphereCone: a sphere under a similarity, uniformly in the cone of directions it subtends
//   (only visible points); from inside it, and from a point on its own surface (shading point of
//   that same sphere), uniformly by area. A point on the surface is classified by what it is,
//   never by |p - c|^2 > r^2: rounding puts about a third of a sphere's own hit points
//   "outside", where the cone degenerates to the point itself;
// - WorldArea (quad, disk, triangle) and MeshArea (a triangle by world area, then uniform on it):
//   uniformly by world area;
// - ObjectArea (sphere under a non-uniform transform, ellipsoid, box, cylinder, capsule):
//   uniformly by area in object space, mapped to world space. The world density then varies
//   over the surface by the Jacobian of the map: for a linear part L and the world normal n at
//   the point, dA_world = |det L| / |L^T n| dA_object (Nanson's formula), so
//   p_world = p_object |L^T n| / |det L|, evaluated the same way for sampled and hit points.
// Points on the back of a one-sided emitter, or hidden behind the emitter itself, are sampled
// and return nothing (the shadow ray or the emission side test rejects them): wasteful for closed
// shapes, but unbiased, and the BSDF strategy covers the same directions in MIS.
//
// A light is chosen with probability proportional to its (estimated) power: luminance of the
// emission times area (times 2 when two-sided), the area as the shape's home states it (a
// stand-in for curved shapes under non-uniform scales): any positive weight is unbiased, and
// pdf() uses exactly the probabilities sample() used.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "raytracer/geometry/shapes/shape_light.hpp"
#include "raytracer/geometry/surface_hit.hpp"
#include "raytracer/render/planted_defect.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

struct LightSample {
    glm::vec3 point{0.0f};
    glm::vec3 point_error{0.0f};  // per-axis bound of the sampled point's rounding error
    glm::vec3 normal{0.0f};       // unit outward (front) normal of the light at `point`
    glm::vec3 wi{0.0f};           // unit, from the shading point toward `point`
    float distance = 0.0f;
    float pdf = 0.0f;             // solid angle at the shading point, light selection included
    glm::vec3 radiance{0.0f};     // emitted toward the shading point (non-zero when returned)
};

class LightSet {
public:
    // PlantedDefect::FlippedNormals turns the sampled points' normals inward too, so the planted
    // bug acts on light sampling as it does on the intersector's hits.
    explicit LightSet(const Scene& scene, PlantedDefect defect = PlantedDefect::None);

    bool empty() const { return lights_.empty(); }
    std::size_t size() const { return lights_.size(); }
    bool is_light(std::uint32_t object) const {
        return object < light_of_object_.size() && light_of_object_[object] >= 0;
    }
    // Probability of choosing the light made of `object` (0 if it is not one).
    float selection_probability(std::uint32_t object) const;

    // Marks a shading point that lies on no object's surface (a camera, a test probe).
    static constexpr std::uint32_t kNoObject = 0xffffffffu;

    // A point on a light seen from shading point `p`, from four uniforms in [0, 1). `p_object`
    // is the object whose surface `p` lies on (kNoObject if none): a sphere light samples itself
    // by area from its own surface. Returns false when the sample carries no light (back side of
    // a one-sided emitter, degenerate).
    bool sample(const glm::vec3& p, std::uint32_t p_object, float u_select, float u_part, float u1, float u2,
                LightSample& out) const;

    // Solid-angle density (selection included) with which sample(p, p_object, ...) produces the
    // light point `hit`, reached from `p` by a ray. Zero when hit.object is not a light.
    float pdf(const glm::vec3& p, std::uint32_t p_object, const SurfaceHit& hit) const;

private:
    struct Light {
        std::uint32_t object = 0;
        float probability = 0.0f;  // selection probability
        const Material* material = nullptr;
        ShapeLight shape;          // what the object's shape home set up (geometry/shapes/)
        const Shape* geometry = nullptr;
        void (*sample_surface)(const Shape&, const ShapeLight&, float, float, float, SurfacePoint&) = nullptr;
    };

    bool sample_cone(const Light& l, const glm::vec3& p, std::uint32_t p_object, float u1, float u2, LightSample& out,
                     bool& sampled) const;
    float sample_area(const Light& l, float u_part, float u1, float u2, SurfacePoint& world) const;

    const Scene* scene_ = nullptr;
    float normal_sign_ = 1.0f;                  // -1 under PlantedDefect::FlippedNormals
    std::vector<Light> lights_;
    std::vector<float> cdf_;                    // cumulative selection weights, normalised
    std::vector<std::int32_t> light_of_object_; // object index -> light index or -1
};

}  // namespace sweeptrace
