#include <stdexcept>

#include "raytracer/accel/accel.hpp"
#include "raytracer/accel/bvh_accel.hpp"
#include "raytracer/accel/embree_accel.hpp"

namespace sweeptrace {

std::unique_ptr<Accel> make_accel(AccelKind kind, const Scene& scene) {
    switch (kind) {
        case AccelKind::Bvh: return std::make_unique<BvhAccel>(scene);
        case AccelKind::Embree: return make_embree_accel(scene);
    }
    throw std::invalid_argument("make_accel: unknown AccelKind");
}

}  // namespace sweeptrace
