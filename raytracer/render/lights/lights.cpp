#include "raytracer/render/lights/lights.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "collision/float_error.hpp"
#include "raytracer/geometry/object_space.hpp"
#include "raytracer/geometry/shapes/uv_maps.hpp"
#include "raytracer/render/materials/bsdf.hpp"
#include "raytracer/render/guiding/light_guide.hpp"
#include "raytracer/render/sampling/sampling.hpp"
#include "raytracer/render/materials/texture.hpp"

namespace sweeptrace {

namespace {

using collision::gamma;
using Strategy = ShapeLight::Strategy;

// The cone a sphere (centre c, radius r) subtends from p, or false when p is inside it or on it
// (`on_sphere`: p is a hit point of this sphere). Both sample() and pdf() decide cone-or-area
// through this one function, so they always agree. A point on the sphere must not be classified
// by |p - c|^2 > r^2: its rounding error (gamma(7) r per axis) decides that comparison, and a
// point rounded outside gets a cone of half-angle ~90 degrees whose visible cap is the point
// itself, so every sample lands at p and the MIS density of the far wall is the cone's 1/(2 pi)
// though the cone never produces it: measured inside a unit sphere, 34 % of hit points fell
// "outside" and their one-bounce estimate was 0.31 instead of 0.5.
struct Cone {
    float dc2 = 0.0f, sin2_max = 0.0f, omc = 0.0f;  // |p - c|^2, sin^2(theta_max), 1 - cos(theta_max)
};
bool cone_from(const glm::vec3& c, float r, const glm::vec3& p, bool on_sphere, Cone& cone) {
    if (on_sphere) return false;
    const glm::vec3 to_p = p - c;
    cone.dc2 = glm::dot(to_p, to_p);
    const float r2 = r * r;
    if (!(cone.dc2 > r2)) return false;
    cone.sin2_max = r2 / cone.dc2;
    const float cos_max = std::sqrt(std::max(0.0f, 1.0f - cone.sin2_max));
    cone.omc = cone.sin2_max / (1.0f + cos_max);  // 1 - cos, without cancellation for small cones
    return true;
}

// The home's surface sampler for one shape kind, bound to a light once at construction so that a
// sample costs one indirect call, not a dispatch on the shape.
template <class Home>
void sample_home(const Shape& shape, const ShapeLight& l, float u_part, float u1, float u2, SurfacePoint& out) {
    Home::sample(*std::get_if<typename Home::Geometry>(&shape), l, u_part, u1, u2, out);
}

// Nanson's formula: dA_world = |det L| / |L^T n| dA_object for world normal n.
float object_area_pdf(const ShapeLight& l, const glm::vec3& n) {
    return l.area_pdf * glm::length(glm::transpose(l.linear) * n) * l.inv_abs_det;
}

}  // namespace

LightSet::LightSet(const Scene& scene, PlantedDefect defect)
    : scene_(&scene),
      normal_sign_(defect == PlantedDefect::FlippedNormals ? -1.0f : 1.0f),
      light_of_object_(scene.objects.size(), -1) {
    std::vector<float> weights;
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        const Object& obj = scene.objects[i];
        const Material& mat = scene.materials[obj.material];
        const float lum = luminance(mat.emission);
        if (!(lum > 0.0f)) continue;
        Light l;
        l.object = i;
        l.material = &mat;
        l.shape = visit_shape(obj.shape, [&](auto home, const auto& g) {
            return decltype(home)::light(g, obj.transform, scene.meshes);
        });
        l.geometry = &obj.shape;
        l.sample_surface = visit_shape(obj.shape, [](auto home, const auto&) { return &sample_home<decltype(home)>; });
        const float weight = lum * l.shape.area * (mat.two_sided_emission ? 2.0f : 1.0f);
        const float area_pdf = l.shape.area_pdf;
        if (!(weight > 0.0f) || !std::isfinite(weight) || !(area_pdf > 0.0f) || !std::isfinite(area_pdf)) continue;
        light_of_object_[i] = static_cast<std::int32_t>(lights_.size());
        lights_.push_back(std::move(l));
        weights.push_back(weight);
    }
    add_scene_lights(scene, weights);
    // Selection. The lights at infinity (directional lights, suns, the environment) together get
    // the share pbrt-v4's BVHLightSampler gives them, n_infinite / (n_infinite + 1) when the scene
    // also has lights at finite places (all of it otherwise), fixed rather than grown with the
    // scene's radius (a power for them, E pi R^2, needs a size: the geometry's extent, not the
    // light, then set their share). Among themselves they split it by E, the irradiance each
    // gives a disc facing it, which needs no size (for the environment the largest over the
    // disc's orientations, as a sun's E is for the disc facing it; its int lum(L) d omega, used
    // before, counts a whole sphere no disc receives, 4x a uniform sky's largest irradiance); the
    // finite lights split the rest by power. pbrt-v4 splits the infinite share equally instead:
    // on classroom (a sun of E = 10 and a sky of 3.5 by the integral) that made the mean
    // per-pixel variance 1.3 to 1.5x the integral split's at equal spp; the largest irradiance,
    // 1.65 there, gives the sun 86% of the picks instead of 74% and 0.87x the integral split's
    // per-sample variance (docs/noise-forensics.md). Any positive probabilities are unbiased:
    // sample() and pdf() read the same ones.
    const std::size_t n = weights.size();
    std::vector<bool> infinite(n, false);
    for (std::size_t k = lights_.size(); k < n; ++k)
        infinite[k] = k == lights_.size() + scene_lights_.size() ||
                      scene_lights_[k - lights_.size()].light->type == SceneLight::Type::Directional;
    double finite_total = 0.0, infinite_total = 0.0;
    std::size_t n_infinite = 0;
    for (std::size_t k = 0; k < n; ++k) {
        if (infinite[k]) {
            ++n_infinite;
            infinite_total += weights[k];
        } else {
            finite_total += weights[k];
        }
    }
    const double infinite_share =
        n_infinite == 0 ? 0.0 : double(n_infinite) / double(n_infinite + (finite_total > 0.0 ? 1 : 0));
    const double finite_share = 1.0 - infinite_share;
    double running = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const double p = infinite[k] ? infinite_share * weights[k] / infinite_total : finite_share * weights[k] / finite_total;
        const float probability = static_cast<float>(p);
        if (k < lights_.size()) {
            lights_[k].probability = probability;
        } else if (k == lights_.size() + scene_lights_.size()) {
            background_probability_ = probability;
        } else {
            NonSurfaceLight& l = scene_lights_[k - lights_.size()];
            l.probability = probability;
            if (l.sun >= 0) suns_[static_cast<std::size_t>(l.sun)].probability = probability;
        }
        running += p;
        cdf_.push_back(static_cast<float>(running));
    }
    if (!cdf_.empty()) cdf_.back() = 1.0f;
    // The guidable sky's probability where a guide makes it a light: the share the rule above
    // would give it as one more light at infinity (1 when it is the only light); the other
    // lights keep their proportions in the rest.
    if (sky_) {
        const double with_sky = double(n_infinite + 1) / double(n_infinite + 1 + (finite_total > 0.0 ? 1 : 0));
        sky_probability_ = static_cast<float>(with_sky * double(sky_weight_) / (infinite_total + double(sky_weight_)));
        if (cdf_.empty()) sky_probability_ = 1.0f;
    }
}

// The light's emission toward -out.wi at out.point: its material's constant, or its emission
// texture read at that point (the material's `emission` is then the texture's mean, the
// selection weight: the side test is the same, the value the texel's).
glm::vec3 LightSet::emitted_radiance_at(const Light& l, const LightSample& out, std::uint32_t primitive) const {
    const glm::vec3 le = emitted_radiance(*l.material, out.normal, -out.wi);
    if (l.material->emission_texture < 0 || le == glm::vec3(0.0f)) return le;
    SurfaceHit at;
    at.point = out.point;
    at.object = l.object;
    at.primitive = primitive;
    return textured_emission(*scene_, *l.material, at);
}

float LightSet::selection_probability(std::uint32_t object) const {
    return is_light(object) ? lights_[static_cast<std::size_t>(light_of_object_[object])].probability : 0.0f;
}

std::int32_t LightSet::escaped_light(const glm::vec3& dir) const {
    for (std::size_t k = 0; k < scene_lights_.size(); ++k) {
        const int sun = scene_lights_[k].sun;
        if (sun >= 0 && glm::dot(dir, suns_[static_cast<std::size_t>(sun)].to_light) >= suns_[static_cast<std::size_t>(sun)].cos_max)
            return static_cast<std::int32_t>(lights_.size() + k);
    }
    return background_ ? static_cast<std::int32_t>(lights_.size() + scene_lights_.size()) : -1;
}

std::string LightSet::light_name(std::int32_t light) const {
    const auto k = static_cast<std::size_t>(light);
    if (light < 0 || k > lights_.size() + scene_lights_.size()) return "?";
    if (k < lights_.size()) {
        const std::string& name = scene_->objects[lights_[k].object].name;
        return name.empty() ? "object " + std::to_string(lights_[k].object) : name;
    }
    if (k == lights_.size() + scene_lights_.size())
        return !background_ ? "?" : scene_->background.kind == Background::Kind::Environment ? "environment" : "sky";
    const std::string& name = scene_lights_[k - lights_.size()].light->name;
    return name.empty() ? "light " + std::to_string(k - lights_.size()) : name;
}

// The inverse of sample_cone's map: the point of the sample square from which the cone gives
// the light point `q` seen from `p`. u1 from the angle to the cone's axis (1 - cos by the half
// chord, which keeps narrow cones' precision), u2 from the azimuth of q's normal in the frame
// sample_cone builds about the centre-to-p axis.
namespace {
glm::vec2 cone_square(const ShapeLight& s, const glm::vec3& p, const glm::vec3& q, const Cone& cone) {
    const glm::vec3 to_p = p - s.origin;
    const float dc = std::sqrt(cone.dc2);
    const glm::vec3 w = glm::normalize(q - p);
    const glm::vec3 chord = w + to_p / dc;  // w - axis, the axis pointing from p to the centre
    const float one_minus_cos = 0.5f * glm::dot(chord, chord);
    const Frame f(to_p / dc);
    const glm::vec3 n = f.to_local((q - s.origin) / s.radius);
    return {std::clamp(one_minus_cos / cone.omc, 0.0f, kBelowOne), std::min(uv_maps::longitude(n.x, n.y), kBelowOne)};
}
}  // namespace

// Cone sampling (pbrt-v3 §14.2): a direction in the subtended cone, then the point where it first
// meets the sphere, found through the angle at the centre. False when p sees no cone (inside, or
// on this sphere): the caller samples by area then.
bool LightSet::sample_cone(const Light& l, const glm::vec3& p, std::uint32_t p_object, float u1, float u2,
                           float square_density, LightSample& out, bool& sampled) const {
    const ShapeLight& s = l.shape;
    Cone cone;
    sampled = cone_from(s.origin, s.radius, p, p_object == l.object, cone);
    if (!sampled) return false;
    const float dc = std::sqrt(cone.dc2);
    const glm::vec3 to_p = p - s.origin;
    const glm::vec3 d = uniform_cone(u1, u2, cone.omc);
    const float sin2_t = d.x * d.x + d.y * d.y;
    const float cos_t = d.z;
    // cos(alpha) in pbrt-v4's form (§6.2.4), free of the cancellation that the law of cosines
    // suffers for small, far lights.
    const float sin_max = std::sqrt(cone.sin2_max);
    const float cos_a =
        std::clamp(sin2_t / sin_max + cos_t * std::sqrt(std::max(0.0f, 1.0f - sin2_t / cone.sin2_max)), -1.0f, 1.0f);
    const float sin_a = std::sqrt(std::max(0.0f, 1.0f - cos_a * cos_a));
    const float sin_t = std::sqrt(sin2_t);
    // In a frame whose z points from the centre toward p, the point's normal has polar angle
    // alpha; its azimuth is uniform like the direction's (any fixed relation gives the same
    // distribution; this one puts it where the direction meets it).
    const Frame f(to_p / dc);
    const glm::vec3 n = sin_t > 0.0f ? f.to_world(glm::vec3(sin_a * d.x / sin_t, sin_a * d.y / sin_t, cos_a)) : f.n;
    const glm::vec3 q = s.origin + s.radius * n;
    const glm::vec3 w = q - p;
    out.distance = glm::length(w);
    if (!(out.distance > 0.0f)) return false;
    out.wi = w / out.distance;
    out.pdf = l.probability * uniform_cone_pdf(cone.omc) * square_density;
    out.on_square = true;
    out.square = glm::vec2(u1, u2);
    out.point = q;
    out.point_error = gamma(5) * (glm::abs(s.origin) + glm::vec3(s.radius));
    out.normal = normal_sign_ * n;
    out.radiance = emitted_radiance_at(l, out, 0);
    return out.pdf > 0.0f && std::isfinite(out.pdf) && luminance(out.radiance) > 0.0f;
}

// A world point uniform by area on the light's surface (the object's home draws it), with its
// error and unit normal; returns its area density.
float LightSet::sample_area(const Light& l, float u_part, float u1, float u2, SurfacePoint& world) const {
    const ShapeLight& s = l.shape;
    if (s.strategy == Strategy::WorldArea || s.strategy == Strategy::SphereCone) {
        l.sample_surface(*l.geometry, s, u_part, u1, u2, world);
        return s.area_pdf;
    }
    SurfacePoint local;
    l.sample_surface(*l.geometry, s, u_part, u1, u2, local);
    affine_point_to_world(s.to_world, local.point, local.error, world.point, world.error);
    world.normal = glm::normalize(s.normal_to_world * local.normal);
    world.primitive = local.primitive;
    return s.strategy == Strategy::ObjectArea ? object_area_pdf(s, world.normal) : s.area_pdf;
}

bool LightSet::sample(const glm::vec3& p, std::uint32_t p_object, float u_select, float u_part, float u1, float u2,
                      LightSample& out, const DirectionalQuadtree* square_guide,
                      const SkyGuide* sky_guide) const {
    if (sky_guide == nullptr || !sky_) return sample_lights(p, p_object, u_select, u_part, u1, u2, out, square_guide);
    const float ps = sky_probability_;
    if (u_select < ps) return sample_guided_sky(*sky_guide, p, u1, u2, out);
    if (!sample_lights(p, p_object, std::min((u_select - ps) / (1.0f - ps), kBelowOne), u_part, u1, u2, out, square_guide))
        return false;
    out.pdf *= 1.0f - ps;
    return true;
}

bool LightSet::sample_lights(const glm::vec3& p, std::uint32_t p_object, float u_select, float u_part, float u1,
                             float u2, LightSample& out, const DirectionalQuadtree* square_guide) const {
    if (cdf_.empty()) return false;
    const auto it = std::upper_bound(cdf_.begin(), cdf_.end(), u_select);
    const auto index = static_cast<std::size_t>(std::min<std::ptrdiff_t>(it - cdf_.begin(), cdf_.size() - 1));
    out.light = static_cast<std::int32_t>(index);
    if (index >= lights_.size()) {  // one test on the emissive objects' path
        const std::size_t k = index - lights_.size();
        return k < scene_lights_.size() ? sample_scene_light(scene_lights_[k], p, u1, u2, out)
                                        : sample_background(p, u1, u2, out);
    }
    const Light& l = lights_[index];
    if (l.shape.strategy == Strategy::SphereCone) {
        // The guide's warp here, not inside sample_cone: there its branch (with calls into the
        // quadtree) kept the cone's square roots and divisions from overlapping, and the
        // unguided cone sample cost ~35% more (perf, smallpt). Where p sees no cone the light is
        // sampled by area from the unwarped u1, u2, and pdf() applies no mixture either.
        float square_density = 1.0f;
        const glm::vec2 w = square_guide == nullptr ? glm::vec2(u1, u2)
                                                    : warp_light_sample(*square_guide, glm::vec2(u1, u2), square_density);
        bool cone = false;
        const bool ok = sample_cone(l, p, p_object, w.x, w.y, square_density, out, cone);
        if (cone) return ok;
    }
    SurfacePoint sp;
    const float area_pdf = sample_area(l, u_part, u1, u2, sp);
    const glm::vec3& q = sp.point;
    const glm::vec3& n = sp.normal;
    const glm::vec3 w = q - p;
    const float d2 = glm::dot(w, w);
    out.distance = std::sqrt(d2);
    if (!(out.distance > 0.0f)) return false;
    out.wi = w / out.distance;
    const float cos_l = std::abs(glm::dot(n, out.wi));
    if (!(cos_l > 0.0f)) return false;
    out.pdf = l.probability * area_pdf * d2 / cos_l;
    out.point = q;
    out.point_error = sp.error;
    out.normal = normal_sign_ * n;
    out.radiance = emitted_radiance_at(l, out, sp.primitive);
    return std::isfinite(out.pdf) && luminance(out.radiance) > 0.0f;
}

float LightSet::pdf(const glm::vec3& p, std::uint32_t p_object, const SurfaceHit& hit,
                    const DirectionalQuadtree* square_guide, const SkyGuide* sky_guide) const {
    const float pdf = lights_pdf(p, p_object, hit, square_guide);
    return sky_guide != nullptr && sky_ ? pdf * (1.0f - sky_probability_) : pdf;
}

float LightSet::lights_pdf(const glm::vec3& p, std::uint32_t p_object, const SurfaceHit& hit,
                           const DirectionalQuadtree* square_guide) const {
    if (!is_light(hit.object)) return 0.0f;
    const Light& l = lights_[static_cast<std::size_t>(light_of_object_[hit.object])];
    float area_pdf = l.shape.area_pdf;
    if (l.shape.strategy == Strategy::SphereCone) {
        Cone cone;
        if (cone_from(l.shape.origin, l.shape.radius, p, p_object == l.object, cone)) {
            const float pdf = l.probability * uniform_cone_pdf(cone.omc);
            if (square_guide == nullptr) return pdf;
            return pdf * light_square_density(*square_guide, cone_square(l.shape, p, hit.point, cone));
        }
    } else if (l.shape.strategy == Strategy::ObjectArea) {
        area_pdf = object_area_pdf(l.shape, hit.normal);
    }
    const glm::vec3 w = hit.point - p;
    const float d2 = glm::dot(w, w);
    const float cos_l = std::abs(glm::dot(hit.normal, w)) / std::sqrt(d2);
    if (!(cos_l > 0.0f)) return 0.0f;
    return l.probability * area_pdf * d2 / cos_l;
}

}  // namespace sweeptrace
