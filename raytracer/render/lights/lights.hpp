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
// Which light: the lights at infinity (directional lights, suns, the environment) together get
// the share pbrt-v4's BVHLightSampler gives them, n_infinite / (n_infinite + 1) when the scene
// also has lights at finite places (else all of it), and split it by the irradiance E each gives
// a disc facing it (for the environment, the largest over the disc's orientations:
// EnvironmentLight::max_irradiance); the finite ones (emissive objects,
// points, spots) share the rest in proportion to their (estimated) power / pi: an emitter's
// luminance of the emission times area (times 2 when two-sided, the area as the shape's home
// states it, a stand-in for curved shapes under non-uniform scales), a point light 4 I, a spot
// 2 I (1 - (cos_start + cos_cone) / 2). A power for a light at infinity would need the scene's
// size (E pi R^2): the room around a lamp, not the light, then set the sky's share. Any positive
// probabilities are unbiased, and pdf() uses exactly the probabilities sample() used.
//
// The scene's "lights" (scene/scene_light.hpp; render/lights/scene_lights.cpp) join the same selection,
// after the emissive objects. Strategies:
// - Point and spot: the one direction toward the position, pdf = selection probability, marked
//   delta (no MIS: a BSDF-sampled ray never finds a point);
// - Directional with angular_diameter 0: the one direction, delta likewise, shadow ray to infinity;
// - Directional with a disc of directions (a sun): uniform in its cone of half-angle alpha, of
//   radiance L = E / (pi sin^2 alpha), so the irradiance on a surface facing it is E whatever
//   the diameter; BSDF-sampled rays that escape into the cone find it too (escaped_radiance),
//   weighted by MIS against the same cone density.
// - An emitting background (render/lights/background_light.hpp: an environment map, or a colour or the
//   sky with a portal) is one more light at infinity, last (scene_lights.cpp says why not without);
//   sampled as BackgroundLight draws it from the shading point, found by escaped rays, MIS weighted.
// - A colour or the sky without a portal is a light only at path vertices where path guiding
//   learned where it is seen (render/guiding/sky_guide.hpp): sample(), pdf(), escaped_radiance()
//   and guided_sky_weight() take that vertex's `sky_guide`. There the sky is chosen with
//   probability sky_probability() (what the selection above would give it as a light at infinity;
//   1 in a scene without other lights) and every other light's probability is scaled by
//   1 - sky_probability(); without a guide nothing changes. bdpt and vcm pass no guide.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "collision/bounds3.hpp"
#include "raytracer/geometry/shapes/shape_light.hpp"
#include "raytracer/geometry/surface_hit.hpp"
#include "raytracer/render/lights/background_light.hpp"
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
    // A point or a single direction: `pdf` is the selection probability alone and no BSDF
    // sample can find the light, so the sample takes MIS weight 1 and `radiance` is what the
    // light delivers (intensity / d^2 for points, irradiance for directions).
    bool delta = false;
    // At infinity (directional): the shadow ray goes along `wi` without end; `point` is unused.
    bool at_infinity = false;
    // Drawn by a cone (a sphere light seen from outside) from `square`, the point of its sample
    // square the two uniforms became (warped when NEE was guided: light_guide.hpp).
    bool on_square = false;
    glm::vec2 square{0.0f};
    // Which light was chosen (LightSet::light_name): noise forensics name the light with it
    // (-1 for the guided sky, which has no place in the selection order).
    std::int32_t light = -1;
    // The sky without a portal, drawn from a vertex's learned sky guide (sky_guide.hpp).
    bool guided_sky = false;
};

class DirectionalQuadtree;
struct SkyGuide;

// A light's emission sampled for light tracing and bidirectional methods
// (LightSet::sample_emission): a point and the direction light leaves it in.
struct LightEmission {
    glm::vec3 point{0.0f};        // on the surface; the point light's position; on the disc (at infinity)
    glm::vec3 point_error{0.0f};
    glm::vec3 normal{0.0f};       // unit outward normal of a surface light (zero for points; `dir` at infinity)
    glm::vec3 dir{0.0f};          // unit, the way the light travels
    // Radiance (surfaces, suns, environment), intensity with the spot's falloff (points, spots),
    // irradiance (a directional light without a disc).
    glm::vec3 le{0.0f};
    float pdf_pos = 0.0f;  // area density of `point` (1 for a point light), selection not included
    float pdf_dir = 0.0f;  // solid-angle density of `dir` (1 for a delta direction)
    float selection = 0.0f;
    std::uint32_t light = 0;  // the light's index in the selection order (LightSet::light_of_sample)
    std::uint32_t object = 0xffffffffu, primitive = 0;  // a surface light's object and triangle
    bool delta_position = false;   // point, spot
    bool delta_direction = false;  // a directional light without a disc
    bool at_infinity = false;      // directional, sun, environment: `point` is on a disc of the
                                   // scene's bounding sphere, facing `dir`
};

class LightSet {
public:
    // PlantedDefect::FlippedNormals turns the sampled points' normals inward too, so the planted
    // bug acts on light sampling as it does on the intersector's hits.
    explicit LightSet(const Scene& scene, PlantedDefect defect = PlantedDefect::None);

    bool empty() const { return cdf_.empty(); }
    std::size_t size() const { return lights_.size(); }
    bool is_light(std::uint32_t object) const {
        return object < light_of_object_.size() && light_of_object_[object] >= 0;
    }
    // Probability of choosing the light made of `object` (0 if it is not one).
    float selection_probability(std::uint32_t object) const;
    // Lights by index, in selection order (emissive objects, scene lights, environment), for
    // reports: the index of the light made of `object` (-1 if none), of the sun whose cone holds
    // the escaped direction `dir` or else the environment (-1 if neither), and a light's name.
    std::int32_t light_of_object(std::uint32_t object) const { return is_light(object) ? light_of_object_[object] : -1; }
    std::int32_t escaped_light(const glm::vec3& dir) const;
    std::string light_name(std::int32_t light) const;
    std::int32_t light_count() const { return static_cast<std::int32_t>(cdf_.size()); }

    // Marks a shading point that lies on no object's surface (a camera, a test probe).
    static constexpr std::uint32_t kNoObject = 0xffffffffu;

    // A point on a light seen from shading point `p`, from four uniforms in [0, 1). `p_object`
    // is the object whose surface `p` lies on (kNoObject if none): a sphere light samples itself
    // by area from its own surface. Returns false when the sample carries no light (back side of
    // a one-sided emitter, degenerate).
    // With `square_guide`, a cone-sampled light draws its square point from the guide's
    // defensive mixture (light_guide.hpp) and `pdf` includes that mixture's density. With
    // `sky_guide` (only when sky_is_guidable()), the sky without a portal is one more light
    // (sky_guide.hpp); u_select picks it or the others, stretched back over [0, 1).
    bool sample(const glm::vec3& p, std::uint32_t p_object, float u_select, float u_part, float u1, float u2,
                LightSample& out, const DirectionalQuadtree* square_guide = nullptr,
                const SkyGuide* sky_guide = nullptr) const;

    // Solid-angle density (selection included) with which sample(p, p_object, ...) produces the
    // light point `hit`, reached from `p` by a ray. Zero when hit.object is not a light.
    // `square_guide` and `sky_guide` as given to sample() from p.
    float pdf(const glm::vec3& p, std::uint32_t p_object, const SurfaceHit& hit,
              const DirectionalQuadtree* square_guide = nullptr, const SkyGuide* sky_guide = nullptr) const;

    // True when some light sits at infinity with a disc of directions (a sun): rays that escape
    // the scene must then ask escaped_radiance.
    bool has_distant() const { return !suns_.empty() || background_ != nullptr; }
    // True when the background emits and is sampled as a light: escaped_radiance then returns its
    // radiance (MIS weighted) and the integrator must not add it again.
    bool background_is_light() const { return background_ != nullptr; }
    // Radiance of the suns and of the background light along unit direction `dir` of a ray that
    // left point `from` and escaped the scene, each weighted by MIS against next event
    // estimation's density from `from` when `bsdf_pdf` > 0 (the solid-angle density the BSDF
    // sampled `dir` with); `bsdf_pdf` <= 0 gives full weight (camera rays, delta bounces,
    // BSDF-only sampling).
    // `sky_guide` as given to sample() from `from` (the other lights' selection then shrinks).
    glm::vec3 escaped_radiance(const glm::vec3& from, const glm::vec3& dir, float bsdf_pdf,
                               const SkyGuide* sky_guide = nullptr) const;

    // The background emits, has no portal and is no map: no light, but one that a learned sky
    // guide turns into one at the vertices where it was learned (sky_guide.hpp).
    bool sky_is_guidable() const { return sky_ != nullptr; }
    // The guided sky's selection probability where it is a light.
    float sky_probability() const { return sky_probability_; }
    // The MIS weight of the guidable sky's radiance found along `dir` by a ray drawn with density
    // `bsdf_pdf` from `from`, a vertex with `sky_guide` (power heuristic against next event
    // estimation's density of the sky there); 1 without a guide or for bsdf_pdf <= 0, as
    // escaped_radiance.
    float guided_sky_weight(const glm::vec3& from, const glm::vec3& dir, float bsdf_pdf, const SkyGuide* sky_guide) const;

    // --- Emission sampling, for light tracing and bidirectional path tracing
    // (render/lights/light_emission.cpp). The light is chosen with the probabilities sample() uses.
    // Surfaces: a point uniform by area (as sample_area draws it, the sphere too), a direction
    // cosine-distributed about the emitting side (two-sided: a side with probability 1/2).
    // Point: uniform over the sphere; spot: uniform in its cone. Lights at infinity (directional,
    // sun, environment): a direction as NEE draws it, then a point uniform on the disc of the
    // scene's bounding sphere perpendicular to it (pbrt-v4's convention).
    bool sample_emission(float u_select, float u_part, float u1, float u2, float u3, float u4,
                         LightEmission& out) const;
    // The light sample() draws from u_select (its index in the selection order; light_count()
    // and light_of_object() above count in the same order).
    std::uint32_t light_of_sample(float u_select) const;
    float light_selection(std::uint32_t light) const;
    // Lights at infinity that an escaping ray can find (suns with a disc, the environment).
    bool light_is_found_at_infinity(std::uint32_t light) const;
    bool light_is_delta_position(std::uint32_t light) const;
    // A point or spot light's position (light_is_delta_position), where it emits from.
    glm::vec3 delta_light_position(std::uint32_t light) const;
    bool light_is_at_infinity(std::uint32_t light) const;
    // Radiance of a light at infinity along `dir` (toward the light); zero outside a sun's disc.
    glm::vec3 radiance_at_infinity(std::uint32_t light, const glm::vec3& dir) const;
    // The densities sample_emission draws with, for a light's point and direction: selection x
    // area density of a surface point with outward normal `normal` (selection alone for a point
    // light; selection x the solid-angle density of the direction for a light at infinity, pbrt's
    // convention: emission's, which for a background with a portal is not next event
    // estimation's), and the solid-angle density of emitting along `dir` from there (the disc's
    // area density for a light at infinity; 1 for a delta direction).
    struct EmissionDensity {
        float pos = 0.0f, dir = 0.0f;
    };
    EmissionDensity emission_density(std::uint32_t light, const glm::vec3& normal, const glm::vec3& dir) const;
    // What a surface light (radiance) or a point / spot light (intensity, the spot's falloff
    // included) emits along `dir` from its point (normal, primitive: of that point).
    glm::vec3 emission_toward(std::uint32_t light, const glm::vec3& point, const glm::vec3& normal,
                              std::uint32_t primitive, const glm::vec3& dir) const;
    // Next event estimation's density from point `p` for a light at infinity or a point / spot /
    // directional light (selection x the direction's solid-angle density; selection alone for
    // delta lights). Only a background with a portal depends on `p`.
    float nee_density_of_light(std::uint32_t light, const glm::vec3& p, const glm::vec3& to_light) const;

private:
    struct Light {
        std::uint32_t object = 0;
        float probability = 0.0f;  // selection probability
        const Material* material = nullptr;
        ShapeLight shape;          // what the object's shape home set up (geometry/shapes/)
        const Shape* geometry = nullptr;
        void (*sample_surface)(const Shape&, const ShapeLight&, float, float, float, SurfacePoint&) = nullptr;
    };

    glm::vec3 emitted_radiance_at(const Light& l, const LightSample& out, std::uint32_t primitive) const;
    // (u1, u2) the point of the sample square, drawn with density square_density there (1:
    // uniform; light_guide.hpp's mixture otherwise).
    bool sample_cone(const Light& l, const glm::vec3& p, std::uint32_t p_object, float u1, float u2,
                     float square_density, LightSample& out, bool& sampled) const;
    float sample_area(const Light& l, float u_part, float u1, float u2, SurfacePoint& world) const;

    // The scene's "lights" (render/lights/scene_lights.cpp).
    struct Sun {
        glm::vec3 to_light{0.0f};  // unit, toward the light
        float cos_max = 1.0f, omc = 0.0f;  // cos(alpha), 1 - cos(alpha)
        glm::vec3 radiance{0.0f};
        float probability = 0.0f;
    };
    struct NonSurfaceLight {
        const SceneLight* light = nullptr;
        float probability = 0.0f;
        int sun = -1;  // index into suns_ for a directional light with a disc of directions
    };
    void add_scene_lights(const Scene& scene, std::vector<float>& weights);
    bool sample_scene_light(const NonSurfaceLight& l, const glm::vec3& p, float u1, float u2, LightSample& out) const;
    bool sample_background(const glm::vec3& p, float u1, float u2, LightSample& out) const;
    bool sample_guided_sky(const SkyGuide& sky_guide, const glm::vec3& p, float u1, float u2, LightSample& out) const;
    // The regular selection without the guided sky, as sample() scales it by the sky's presence.
    bool sample_lights(const glm::vec3& p, std::uint32_t p_object, float u_select, float u_part, float u1, float u2,
                       LightSample& out, const DirectionalQuadtree* square_guide) const;
    float lights_pdf(const glm::vec3& p, std::uint32_t p_object, const SurfaceHit& hit,
                     const DirectionalQuadtree* square_guide) const;

    const Scene* scene_ = nullptr;
    float normal_sign_ = 1.0f;                  // -1 under PlantedDefect::FlippedNormals
    std::vector<Light> lights_;
    std::vector<float> cdf_;                    // cumulative selection weights, normalised
    std::vector<std::int32_t> light_of_object_; // object index -> light index or -1
    std::vector<NonSurfaceLight> scene_lights_; // after lights_ in cdf_
    std::vector<Sun> suns_;
    std::shared_ptr<const BackgroundLight> background_;  // the background, when it emits
    // The sphere around the scene's bounds, set when a light sits at infinity (emission sampling).
    glm::vec3 bounds_centre_{0.0f};
    float bounds_radius_ = 1.0f;
    bool emit_scene_light(const NonSurfaceLight& l, float u1, float u2, float u3, float u4, LightEmission& out) const;
    float background_probability_ = 0.0f;          // it is the last entry of cdf_
    // The background that only a learned guide makes a light (sky_is_guidable), its weight (E, as
    // the lights at infinity are weighed) and its selection probability where it is one.
    std::shared_ptr<const BackgroundLight> sky_;
    float sky_weight_ = 0.0f;
    float sky_probability_ = 0.0f;
};

// Every object's world box together (object_world_bounds; empty for a scene without objects): the
// extent lights at infinity emit over, and what vcm's default merging radius is a fraction of.
collision::Bounds3 scene_world_bounds(const Scene& scene);

}  // namespace sweeptrace
