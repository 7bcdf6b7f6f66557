#pragma once
// A participating medium as the scene gives it (scene key "media"; render/media/ samples it).
// Two kinds, pbrt-v4's "homogeneous" and "uniformgrid":
//   - homogeneous: sigma_a and sigma_s (per unit length, RGB) times `scale` everywhere the medium
//     is; an optional emitted radiance `emission` (times sigma_a, as pbrt-v4's Le);
//   - grid: the same coefficients times a density d(p) >= 0 read by trilinear interpolation of
//     nx x ny x nz samples at the voxel centres of the box [p0, p1] of the medium's own space
//     (pbrt-v4's SampledGrid: a sample outside the grid reads 0, so the density fades to 0 over
//     the outer half voxel), zero outside the box; `to_medium` maps world to that space (the
//     transform given with the medium). With emission, an optional per-voxel scale of it
//     (`emission_scale`, the same size as the density).
// The phase function is Henyey-Greenstein with asymmetry g in (-1, 1) (0 isotropic, > 0 forward).
// Where a medium is comes from the surfaces around it (geometry/object.hpp, MediumInterface) and
// the camera's `medium`, never from the medium itself.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace sweeptrace {

struct Medium {
    enum class Kind { Homogeneous, Grid };
    Kind kind = Kind::Homogeneous;
    std::string name;
    glm::vec3 sigma_a{0.0f};  // absorption, per unit length, `scale` already applied
    glm::vec3 sigma_s{0.0f};  // scattering, per unit length, `scale` already applied
    float g = 0.0f;
    glm::vec3 emission{0.0f};  // radiance emitted per unit sigma_a
    // Grid only.
    int nx = 0, ny = 0, nz = 0;
    std::vector<float> density;         // x fastest, then y, then z (pbrt-v4's order)
    std::vector<float> emission_scale;  // empty, or one per density sample
    glm::vec3 p0{0.0f}, p1{1.0f};
    glm::mat4 to_medium{1.0f};          // world -> the medium's own space
};

}  // namespace sweeptrace
