#pragma once
// An object's motion over the camera's shutter: keyframe transforms spaced evenly over it (key 0
// at shutter open, key N-1 at close), interpolated as pbrt-v4's AnimatedTransform does. Each
// key's matrix M is taken apart as M = T R S: T its translation, R the rotation and S the
// symmetric stretch of the polar decomposition of its linear part (R from the iteration
// R <- (R + R^-T) / 2, S = R^T L). Between keys T and S are linear and R is the slerp of unit
// quaternions along the shorter arc. The time of a query is the shutter fraction s in [0, 1]
// (render/camera.hpp draws it per camera ray); the object is seen in pose_at(motion, s).
//
// A pose is a Transform like a still object's: its float to_world is the interpolated matrix
// rounded once, and its to_object is the inverse of that float matrix computed in double and
// rounded once, the property geometry/object_space.cpp's error bounds rest on. At a key's own
// time, and anywhere on a segment whose two keys are equal, the pose is the key's Transform
// itself, bit for bit, so an object that does not move renders as a still one.
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "collision/bounds3.hpp"
#include "raytracer/geometry/transform.hpp"

namespace sweeptrace {

// One key's M = T R S.
struct PoseParts {
    glm::dvec3 translation{0.0};
    glm::dvec4 rotation{1.0, 0.0, 0.0, 0.0};  // unit quaternion (w, x, y, z)
    glm::dmat3 stretch{1.0};                  // symmetric, positive definite
};

struct Motion {
    std::vector<Transform> keys;    // at shutter fractions k / (N - 1); empty: the object is still
    std::vector<PoseParts> parts;   // per key; each rotation on the same side as the one before (shorter arc)
    std::vector<double> angles;     // per segment: the angle it rotates by, radians in [0, pi]
    bool translation_only = false;  // every key has the same linear part: the poses differ by a translation
    glm::dmat3 inverse_linear{1.0}; // then: the inverse, in double, of that (float) linear part

    bool moving() const { return !keys.empty(); }
};

// The motion through `keys` (the transforms at evenly spaced shutter times, first at open).
// Throws std::invalid_argument for fewer than 2 keys or more than kMaxMotionKeys, or a key
// whose linear part is a mirror (negative determinant: no rotation quaternion).
Motion make_motion(std::vector<Transform> keys);
inline constexpr int kMaxMotionKeys = 129;  // Embree's RTC_MAX_TIME_STEP_COUNT

// The pose at shutter fraction s (clamped to [0, 1]). The motion must be moving().
Transform pose_at(const Motion& motion, float s);

// Whether the keys are all one pose (the loader then leaves the object still).
bool keys_equal(const std::vector<Transform>& keys);

// The transform with the float matrix `to_world` (affine, invertible: a pose of a valid
// motion), its inverse computed in double from the float entries and rounded once.
Transform affine_transform(const glm::mat4& to_world);

// A box holding the world image of `object_box` (object space) at every s in [s0, s1]
// (0 <= s0 <= s1 <= 1): each segment's stretch of the interval is cut into kRotationSteps
// pieces when it rotates (one when it does not, where every point moves linearly), each piece
// bounded by collision::swept_bounds from the poses at its ends and its points' acceleration
// bound (derived in motion.cpp), padded for the rounding of the poses between the ends.
collision::Bounds3 motion_world_bounds(const Motion& motion, const collision::Bounds3& object_box, float s0 = 0.0f,
                                       float s1 = 1.0f);
inline constexpr int kRotationSteps = 16;

// Boxes at `steps` (>= 2) times evenly spaced over the shutter, such that between two
// consecutive times the box linearly interpolated between theirs holds the object (the bounds
// Embree's linear motion blur takes per time step): each is the world box of the pose at its
// time grown by the larger of its two pieces' deviation from the chord (the growth
// motion_world_bounds gives a piece). `steps` - 1 must be a multiple of keys - 1, so that every
// piece lies inside one segment.
std::vector<collision::Bounds3> motion_step_bounds(const Motion& motion, const collision::Bounds3& object_box, int steps);

// The time steps the Embree backend gives a moving object: one per key when no segment rotates,
// kRotationSteps per rotating segment otherwise (at most kMaxMotionKeys).
int motion_time_steps(const Motion& motion);

}  // namespace sweeptrace
