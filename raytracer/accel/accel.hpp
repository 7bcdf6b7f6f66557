#pragma once
// One interface, several acceleration structures over a scene's objects.
#include <cstddef>
#include <memory>
#include <string>

#include "collision/ray.hpp"
#include "raytracer/geometry/surface_hit.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

class Accel {
public:
    virtual ~Accel() = default;
    // Nearest hit with ray.tmin < t < ray.tmax; writes `hit` only when found.
    virtual bool intersect(const collision::Ray& ray, SurfaceHit& hit) const = 0;
    // Any hit with ray.tmin < t < ray.tmax (shadow rays).
    virtual bool occluded(const collision::Ray& ray) const = 0;
    // The same at shutter fraction `time` in [0, 1]: moving objects in their pose then
    // (geometry/motion.hpp). The two queries above see every object at time 0, shutter open. A
    // structure that knows no motion (the tests' own) answers these by the ones above.
    virtual bool intersect(const collision::Ray& ray, float /*time*/, SurfaceHit& hit) const { return intersect(ray, hit); }
    virtual bool occluded(const collision::Ray& ray, float /*time*/) const { return occluded(ray); }
    // Bytes held by the structure itself (nodes, indices, copies), not the scene.
    virtual std::size_t memory_bytes() const = 0;
    virtual std::string name() const = 0;
};

enum class AccelKind { Bvh, Embree };

// The scene must outlive the returned structure.
std::unique_ptr<Accel> make_accel(AccelKind kind, const Scene& scene);

}  // namespace sweeptrace
