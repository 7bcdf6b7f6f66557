#pragma once
// Every emissive object of a scene as a light that next event estimation can sample, and the
// density with which it would have sampled a point that a BSDF-sampled ray found (for MIS).
//
// How each shape is sampled (all exactly: the density used in MIS is the one sampled with):
// - sphere whose transform is a similarity (uniform scale, rotation, translation): uniformly in
//   the cone of directions it subtends (only visible points); from inside it, and from a point
//   on its own surface (shading point of that same sphere): uniformly by area. A point on the
//   surface is classified by what it is, never by |p - c|^2 > r^2: rounding puts about a third
//   of a sphere's own hit points "outside", where the cone degenerates to the point itself;
// - quad, disk, triangle: uniformly by world area (an affine map keeps them flat, with constant
//   area scaling);
// - mesh: a triangle chosen by world area, then uniformly on it (so uniform over the surface);
// - sphere under a non-uniform transform, ellipsoid, box, cylinder, capsule: uniformly by area
//   in object space (the ellipsoid as a scaled unit sphere), mapped to world space. The world
//   density then varies over the surface by the Jacobian of the map: for a linear part L and the
//   world normal n at the point, dA_world = |det L| / |L^T n| dA_object (Nanson's formula), so
//   p_world = p_object |L^T n| / |det L|, evaluated the same way for sampled and hit points.
// Points on the back of a one-sided emitter, or hidden behind the emitter itself, are sampled
// and return nothing (the shadow ray or the emission side test rejects them): wasteful for closed
// shapes, but unbiased, and the BSDF strategy covers the same directions in MIS.
//
// A light is chosen with probability proportional to its (estimated) power: luminance of the
// emission times area (times 2 when two-sided). For shapes whose world area has no closed form
// (non-uniformly scaled curved shapes) the object area times |det L|^(2/3) stands in: any positive
// weight is unbiased, and pdf() uses exactly the probabilities sample() used.
#include <cstdint>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "raytracer/geometry/surface_hit.hpp"
#include "raytracer/render/renderer.hpp"
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
    enum class Kind : std::uint8_t { SphereCone, Parallelogram, Triangle, Ellipse, Surface, Mesh };

    struct Light {
        Kind kind = Kind::Parallelogram;
        std::uint32_t object = 0;
        float probability = 0.0f;  // selection probability
        float area_pdf = 0.0f;     // Parallelogram/Triangle/Ellipse/Mesh/SphereCone-inside: 1/area;
                                   // Surface: the object-space area density
        // SphereCone: center, radius. Parallelogram/Triangle: origin + edges. Ellipse: center +
        // semi-axes. Surface/Mesh: object-to-world affine map.
        glm::vec3 origin{0.0f}, edge_u{0.0f}, edge_v{0.0f};
        float radius = 0.0f;
        glm::vec3 normal{0.0f};  // flat kinds: world front normal
        glm::mat3 linear{1.0f};  // Surface/Mesh: linear part (Surface: with the ellipsoid's radii)
        glm::mat3 normal_to_world{1.0f};
        float inv_abs_det = 1.0f;
        std::uint32_t first_triangle = 0, triangle_count = 0;  // Mesh: range in triangle_cdf_
        const Material* material = nullptr;
    };

    static float surface_area_pdf(const Light& l, const glm::vec3& world_normal);
    bool sample_surface(const Light& l, float u_part, float u1, float u2, glm::vec3& p_obj, glm::vec3& n_obj,
                        glm::vec3& err_obj) const;

    const Scene* scene_ = nullptr;
    float normal_sign_ = 1.0f;                  // -1 under PlantedDefect::FlippedNormals
    std::vector<Light> lights_;
    std::vector<float> cdf_;                    // cumulative selection weights, normalised
    std::vector<std::int32_t> light_of_object_; // object index -> light index or -1
    std::vector<float> triangle_cdf_;           // Mesh lights: cumulative world triangle areas
};

}  // namespace sweeptrace
