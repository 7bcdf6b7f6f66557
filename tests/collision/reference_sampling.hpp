#pragma once
// Seeded random rays for the reference tests: points, directions, rays aimed at a target and
// grazing rays with a chosen closest-approach distance. Direction lengths vary over four
// decades so no routine can silently assume a unit direction.
#include <cmath>
#include <random>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "collision/ray.hpp"

namespace sampling {

struct Sampler {
    std::mt19937_64& rng;

    float uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }
    float log_uniform(float lo, float hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
    glm::vec3 point(float half_extent) {
        return {uniform(-half_extent, half_extent), uniform(-half_extent, half_extent), uniform(-half_extent, half_extent)};
    }
    glm::vec3 direction() {
        for (;;) {
            const glm::vec3 v = point(1.0f);
            const float l2 = glm::dot(v, v);
            if (l2 > 1e-4f && l2 <= 1.0f) return v / std::sqrt(l2);
        }
    }
    // A unit vector perpendicular to unit u.
    glm::vec3 perpendicular(const glm::vec3& u) {
        for (;;) {
            const glm::vec3 p = glm::cross(u, direction());
            const float l2 = glm::dot(p, p);
            if (l2 > 1e-4f) return p / std::sqrt(l2);
        }
    }
    float dir_scale() { return log_uniform(1e-2f, 1e2f); }

    // Origin o toward target, with a random direction length; mostly [0, inf), sometimes a
    // finite window so tmin/tmax selection is exercised too.
    collision::Ray ray_towards(const glm::vec3& o, const glm::vec3& target) {
        glm::vec3 u = target - o;
        const float l = glm::length(u);
        u = l > 0.0f ? u / l : direction();
        const float scale = dir_scale();
        collision::Ray ray{o, u * scale};
        if (uniform(0.0f, 1.0f) < 0.2f) {
            ray.tmin = uniform(0.0f, 1.0f) * l / scale;
            ray.tmax = ray.tmin + uniform(0.0f, 2.0f) * l / scale;
        }
        return ray;
    }

    // A ray whose line passes at distance `closest` from `center`, starting `distance` before
    // the closest-approach point.
    collision::Ray grazing_ray(const glm::vec3& center, float closest, float distance) {
        const glm::vec3 u = direction();
        const glm::vec3 p = center + perpendicular(u) * closest;
        return collision::Ray{p - u * distance, u * dir_scale()};
    }
};

}  // namespace sampling
