#pragma once
// The scene's media at render time: one MediumModel per scene medium, which medium a ray is in
// after it crosses a surface, and the transmittance of a shadow ray, which passes through
// `interface` surfaces (boundaries that do not scatter) and is stopped by any other.
//
// Where media are follows pbrt-v4: a surface whose object gives an inside and an outside medium
// that differ (geometry/object.hpp, MediumInterface) is a boundary, and a ray leaving it toward
// its outward normal's side is in the outside medium, otherwise in the inside one; a surface
// without that keeps the medium the ray arrived in (a wall inside fog reflects into the fog).
// The camera sits in Scene::camera.medium. A ray carries the medium its last boundary gave it;
// that the boundaries nest consistently is checked once before rendering (media_nesting.hpp).
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "collision/ray.hpp"
#include "raytracer/accel/accel.hpp"
#include "raytracer/render/media/medium_model.hpp"
#include "raytracer/render/media/tracking.hpp"
#include "raytracer/render/sampling/random.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

class SceneMedia {
public:
    explicit SceneMedia(const Scene& scene);

    // True when the scene has a medium anywhere or an interface surface: the integrator must
    // then track media and walk shadow rays through interfaces. False: vacuum, nothing changes.
    bool active() const { return active_; }
    const MediumModel& model(std::int32_t medium) const { return models_[static_cast<std::size_t>(medium)]; }

    // The medium (-1: vacuum) a ray in `current` is in after crossing the surface of `object`,
    // whose outward geometric normal is `normal`, heading along `dir`.
    std::int32_t after_crossing(std::uint32_t object, const glm::vec3& normal, const glm::vec3& dir,
                                std::int32_t current) const;

    // Whether the material of the surface `hit` is an interface (the ray passes on unchanged).
    bool is_interface(const SurfaceHit& hit) const;

    // The transmittance of each channel along the shadow ray `ray` (any direction length, over
    // [tmin, tmax]), starting in `medium`: zero if an opaque or scattering surface blocks it,
    // else the product over the media between its ends. After an interface crossing the ray goes
    // on by `next(hit)`, which builds the shadow ray from that hit to the same target. `rays`
    // counts the rays traced.
    template <class Next>
    glm::vec3 shadow_transmittance(const Accel& accel, collision::Ray ray, std::int32_t medium, bool moving, float time,
                                   Rng& rng, std::uint64_t& rays, Next&& next) const;

private:
    const Scene& scene_;
    std::vector<MediumModel> models_;
    bool active_ = false;
};

template <class Next>
glm::vec3 SceneMedia::shadow_transmittance(const Accel& accel, collision::Ray ray, std::int32_t medium, bool moving,
                                           float time, Rng& rng, std::uint64_t& rays, Next&& next) const {
    glm::vec3 tr(1.0f);
    for (;;) {
        SurfaceHit hit;
        const bool found = moving ? accel.intersect(ray, time, hit) : accel.intersect(ray, hit);
        if (found && !is_interface(hit)) return glm::vec3(0.0f);
        if (medium >= 0) {
            // The tracking functions take a unit direction: scale t to world units.
            const float len = glm::length(ray.dir);
            const glm::vec3 d = ray.dir / len;
            tr *= transmittance(model(medium), ray.origin, d, ray.tmin * len, (found ? hit.t : ray.tmax) * len, rng);
            if (tr == glm::vec3(0.0f)) return tr;
        }
        if (!found) return tr;
        medium = after_crossing(hit.object, hit.normal, ray.dir, medium);
        ray = next(hit);
        ++rays;
    }
}

}  // namespace sweeptrace
