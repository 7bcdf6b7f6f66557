#include "raytracer/accel/brute_force_accel.hpp"

#include "raytracer/geometry/intersect_object.hpp"

namespace sweeptrace {
namespace {

class BruteForceAccel final : public Accel {
public:
    explicit BruteForceAccel(const Scene& scene) : scene_(scene) {}

    bool intersect(const collision::Ray& ray, SurfaceHit& hit) const override {
        collision::Ray clipped = ray;
        bool found = false;
        for (std::uint32_t i = 0; i < scene_.objects.size(); ++i) {
            if (intersect_object(scene_.objects, scene_.meshes, i, clipped, hit)) {
                clipped.tmax = hit.t < clipped.tmax ? hit.t : clipped.tmax;
                found = true;
            }
        }
        return found;
    }
    bool occluded(const collision::Ray& ray) const override {
        SurfaceHit unused;
        for (std::uint32_t i = 0; i < scene_.objects.size(); ++i)
            if (intersect_object(scene_.objects, scene_.meshes, i, ray, unused)) return true;
        return false;
    }
    bool intersect(const collision::Ray& ray, float time, SurfaceHit& hit) const override {
        collision::Ray clipped = ray;
        bool found = false;
        for (std::uint32_t i = 0; i < scene_.objects.size(); ++i) {
            if (intersect_object_at(scene_.objects, scene_.meshes, i, clipped, time, hit)) {
                clipped.tmax = hit.t < clipped.tmax ? hit.t : clipped.tmax;
                found = true;
            }
        }
        return found;
    }
    bool occluded(const collision::Ray& ray, float time) const override {
        SurfaceHit unused;
        for (std::uint32_t i = 0; i < scene_.objects.size(); ++i)
            if (intersect_object_at(scene_.objects, scene_.meshes, i, ray, time, unused)) return true;
        return false;
    }
    std::size_t memory_bytes() const override { return sizeof(*this); }
    std::string name() const override { return "brute-force"; }

private:
    const Scene& scene_;
};

}  // namespace

std::unique_ptr<Accel> make_brute_force_accel(const Scene& scene) { return std::make_unique<BruteForceAccel>(scene); }

}  // namespace sweeptrace
