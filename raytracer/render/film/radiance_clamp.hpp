#pragma once
// The opt-in firefly guard of film.clamp_indirect (off by default). Fireflies are rare paths of
// huge weight: in scenes/default.json, diffuse ground -> glass -> a small bright bulb, a caustic
// that next event estimation cannot reach (glass is a delta surface) and BSDF sampling finds once
// in thousands of samples. Limiting such a contribution trades that noise for a known downward
// bias: the energy above the limit is dropped, not spread.
//
// Only indirect light is limited: light that scattered at some vertex after the path's first
// non-delta (rough or diffuse) vertex. So what the camera sees directly, through glass or in a
// mirror, and the direct lighting of the first rough surface it sees that way keep their exact
// values (a bulb's pool of light seen through a glass sphere is not dimmed), while every caustic
// found from a diffuse surface, and all multiple scattering, is limited. The bias this costs on
// the default scene is measured in docs/fireflies.md (tools/clamp_bias.py).
#include <algorithm>

#include <glm/vec3.hpp>

namespace sweeptrace {

class IndirectClamp {
public:
    explicit IndirectClamp(float limit) : limit_(limit) {}

    // The path reached its vertex `depth` (1 = the first hit) and scatters there.
    void scatter_at(int depth, bool delta) {
        if (!delta && first_rough_ == 0) first_rough_ = depth;
    }

    // Light found at vertex `depth` (an emitter hit) or by the ray leaving vertex depth - 1 (an
    // escape): indirect when some vertex after the first rough one lies before it.
    glm::vec3 found(const glm::vec3& contribution, int depth) const {
        return limited(contribution, first_rough_ != 0 && depth >= first_rough_ + 2);
    }

    // Next event estimation's light sample from vertex `depth`.
    glm::vec3 light_sample(const glm::vec3& contribution, int depth) const {
        return limited(contribution, first_rough_ != 0 && depth > first_rough_);
    }

private:
    glm::vec3 limited(const glm::vec3& c, bool indirect) const {
        if (limit_ <= 0.0f || !indirect) return c;
        const float m = std::max({c.x, c.y, c.z});
        return m > limit_ ? c * (limit_ / m) : c;
    }

    float limit_;
    int first_rough_ = 0;  // depth of the first non-delta vertex; 0 = none yet
};

}  // namespace sweeptrace
