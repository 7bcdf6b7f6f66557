#include "raytracer/geometry/motion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "collision/float_error.hpp"
#include "collision/swept_bounds.hpp"
#include "raytracer/geometry/object_space.hpp"

namespace sweeptrace {
namespace {

double frobenius(const glm::dmat3& m) {
    double s = 0.0;
    for (int c = 0; c < 3; ++c) s += glm::dot(m[c], m[c]);
    return std::sqrt(s);
}

// The rotation of the unit quaternion q = (w, x, y, z); glm is column-major: m[column][row].
glm::dmat3 rotation_of(const glm::dvec4& q) {
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    glm::dmat3 m;
    m[0] = {1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y + w * z), 2.0 * (x * z - w * y)};
    m[1] = {2.0 * (x * y - w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z + w * x)};
    m[2] = {2.0 * (x * z + w * y), 2.0 * (y * z - w * x), 1.0 - 2.0 * (x * x + y * y)};
    return m;
}

// The unit quaternion of a proper rotation matrix (Shepperd: divide by the largest of the four
// squared components, so no division is by a small number).
glm::dvec4 quaternion_of(const glm::dmat3& m) {
    const double trace = m[0][0] + m[1][1] + m[2][2];
    glm::dvec4 q;
    if (trace >= m[0][0] && trace >= m[1][1] && trace >= m[2][2]) {
        const double w = 0.5 * std::sqrt(std::max(0.0, 1.0 + trace));
        q = {w, (m[1][2] - m[2][1]) / (4.0 * w), (m[2][0] - m[0][2]) / (4.0 * w), (m[0][1] - m[1][0]) / (4.0 * w)};
    } else if (m[0][0] >= m[1][1] && m[0][0] >= m[2][2]) {
        const double x = 0.5 * std::sqrt(std::max(0.0, 1.0 + m[0][0] - m[1][1] - m[2][2]));
        q = {(m[1][2] - m[2][1]) / (4.0 * x), x, (m[0][1] + m[1][0]) / (4.0 * x), (m[2][0] + m[0][2]) / (4.0 * x)};
    } else if (m[1][1] >= m[2][2]) {
        const double y = 0.5 * std::sqrt(std::max(0.0, 1.0 - m[0][0] + m[1][1] - m[2][2]));
        q = {(m[2][0] - m[0][2]) / (4.0 * y), (m[0][1] + m[1][0]) / (4.0 * y), y, (m[1][2] + m[2][1]) / (4.0 * y)};
    } else {
        const double z = 0.5 * std::sqrt(std::max(0.0, 1.0 - m[0][0] - m[1][1] + m[2][2]));
        q = {(m[0][1] - m[1][0]) / (4.0 * z), (m[2][0] + m[0][2]) / (4.0 * z), (m[1][2] + m[2][1]) / (4.0 * z), z};
    }
    return q / std::sqrt(glm::dot(q, q));
}

// Polar decomposition of an invertible L with det > 0: L = R S.
PoseParts decompose(const glm::mat4& to_world) {
    const glm::dmat4 m(to_world);
    const glm::dmat3 linear(m);
    glm::dmat3 r = linear;
    // Newton's iteration for the orthogonal factor converges quadratically from any invertible
    // start; 100 steps bound the loop for a nearly singular L (from_matrix rejects singular ones).
    for (int i = 0; i < 100; ++i) {
        const glm::dmat3 next = 0.5 * (r + glm::inverse(glm::transpose(r)));
        double change = 0.0;
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k) change = std::max(change, std::fabs(next[c][k] - r[c][k]));
        r = next;
        if (change < 1e-15) break;
    }
    PoseParts p;
    p.translation = glm::dvec3(m[3]);
    p.rotation = quaternion_of(r);
    glm::dmat3 s = glm::transpose(r) * linear;
    p.stretch = 0.5 * (s + glm::transpose(s));  // symmetric up to rounding: made exactly so
    return p;
}

// Slerp from q0 to q1 (q1 on q0's side: dot >= 0) by f in [0, 1]; `half` is acos(dot), half the
// rotation angle between them. The quaternion turns at the constant rate `half` per unit f.
glm::dvec4 slerp(const glm::dvec4& q0, const glm::dvec4& q1, double half, double f) {
    glm::dvec4 q;
    if (half < 1e-9) q = q0 + f * (q1 - q0);  // sin(x) / x = 1 to double precision below this
    else q = (std::sin((1.0 - f) * half) * q0 + std::sin(f * half) * q1) / std::sin(half);
    return q / std::sqrt(glm::dot(q, q));
}

// The pose in segment k (keys k and k + 1) at local fraction f in [0, 1].
Transform pose_in_segment(const Motion& motion, std::size_t k, double f) {
    const Transform& a = motion.keys[k];
    const Transform& b = motion.keys[k + 1];
    if (f <= 0.0 || a.to_world == b.to_world) return a;
    if (f >= 1.0) return b;
    const PoseParts& pa = motion.parts[k];
    const PoseParts& pb = motion.parts[k + 1];
    const glm::dvec3 translation = pa.translation + f * (pb.translation - pa.translation);
    glm::mat4 to_world;
    if (motion.translation_only) {
        to_world = a.to_world;
    } else {
        const glm::dmat3 stretch = pa.stretch + f * (pb.stretch - pa.stretch);
        const glm::dmat3 linear = rotation_of(slerp(pa.rotation, pb.rotation, 0.5 * motion.angles[k], f)) * stretch;
        to_world = glm::mat4(glm::dmat4(linear));
    }
    to_world[3] = glm::vec4(glm::vec3(translation), 1.0f);
    if (!motion.translation_only) return affine_transform(to_world);
    // The shared linear part's inverse, computed once: the same numbers affine_transform gives.
    Transform t;
    t.to_world = to_world;
    const glm::dvec3 back = -(motion.inverse_linear * glm::dvec3(glm::vec3(to_world[3])));
    t.to_object = glm::mat4(glm::dmat4(motion.inverse_linear));
    t.to_object[3] = glm::vec4(glm::vec3(back), 1.0f);
    t.normal_to_world = glm::mat3(glm::transpose(motion.inverse_linear));
    t.identity = to_world == glm::mat4(1.0f);
    return t;
}

double max_corner_length(const collision::Bounds3& box) {
    const glm::dvec3 far = glm::max(glm::abs(glm::dvec3(box.lo)), glm::abs(glm::dvec3(box.hi)));
    return glm::length(far);
}

// The world box over [f0, f1] of segment k, in kRotationSteps pieces per whole segment when it
// rotates. Acceleration of a point p of the box (|p| <= r) along its world path
// w(f) = T(f) + R_k Q(f) S(f) p, Q(f) the rotation by angle(k) * f about slerp's fixed axis,
// T and S linear in f: w'' = R_k (Q'' S p + 2 Q' S' p), so |w''| <= (phi^2 sigma + 2 phi delta) r
// with phi the segment's angle, sigma the larger Frobenius norm of the two stretches (a bound on
// |S(f) p| / |p| by convexity) and delta the norm of their difference. A piece of width h has
// h^2 times that in its own units. The poses used between the ends are rounded: their float
// matrix is within u |M| of the exact one entrywise, which moves a point by at most
// u (sigma r + |T|) per axis; padded by gamma(3) of that.
struct PieceGrowth {
    float accel = 0.0f;  // the acceleration bound of the piece's points, in its own units
    float pad = 0.0f;    // the rounding of the poses between its ends
};

PieceGrowth piece_growth(const Motion& motion, std::size_t k, double h, const collision::Bounds3& box) {
    const double phi = motion.angles[k];
    const PoseParts& pa = motion.parts[k];
    const PoseParts& pb = motion.parts[k + 1];
    if (motion.translation_only) return {};  // linear paths, translations rounded between the ends' floats
    const double r = max_corner_length(box);
    const double sigma = std::max(frobenius(pa.stretch), frobenius(pb.stretch));
    const double delta = frobenius(pb.stretch - pa.stretch);
    const double reach = std::max(glm::length(pa.translation), glm::length(pb.translation));
    PieceGrowth g;
    g.accel = static_cast<float>(h * h * (phi * phi * sigma + 2.0 * phi * delta) * r * (1.0 + 1e-6));
    g.pad = static_cast<float>(collision::gamma(3) * (sigma * r + reach)) * (1.0f + collision::gamma(3));
    return g;
}

collision::Bounds3 grown(collision::Bounds3 b, float by) {
    b.lo -= glm::vec3(by);
    b.hi += glm::vec3(by);
    return b;
}

collision::Bounds3 segment_bounds(const Motion& motion, std::size_t k, double f0, double f1, const collision::Bounds3& box) {
    const int pieces = motion.angles[k] > 0.0 ? std::max(1, static_cast<int>(std::ceil((f1 - f0) * kRotationSteps))) : 1;
    const double h = (f1 - f0) / pieces;
    const PieceGrowth g = piece_growth(motion, k, h, box);
    collision::Bounds3 out;
    collision::Bounds3 before = world_bounds(pose_in_segment(motion, k, f0), box);
    for (int i = 1; i <= pieces; ++i) {
        const collision::Bounds3 after = world_bounds(pose_in_segment(motion, k, f0 + h * i), box);
        out.extend(grown(collision::swept_bounds(before, after, g.accel), g.pad));
        before = after;
    }
    return out;
}

}  // namespace

Transform affine_transform(const glm::mat4& to_world) {
    Transform t;
    t.to_world = to_world;
    const glm::dmat3 inverse = glm::inverse(glm::dmat3(glm::dmat4(to_world)));
    const glm::dvec3 back = -(inverse * glm::dvec3(glm::vec3(to_world[3])));
    t.to_object = glm::mat4(glm::dmat4(inverse));
    t.to_object[3] = glm::vec4(glm::vec3(back), 1.0f);
    t.normal_to_world = glm::mat3(glm::transpose(inverse));
    t.identity = to_world == glm::mat4(1.0f);
    return t;
}

Motion make_motion(std::vector<Transform> keys) {
    if (keys.size() < 2) throw std::invalid_argument("a motion needs at least 2 keys (shutter open and close)");
    if (keys.size() > static_cast<std::size_t>(kMaxMotionKeys))
        throw std::invalid_argument("a motion takes at most " + std::to_string(kMaxMotionKeys) + " keys");
    Motion m;
    m.translation_only = true;
    for (const Transform& k : keys) {
        if (glm::determinant(glm::dmat3(glm::dmat4(k.to_world))) <= 0.0)
            throw std::invalid_argument("a moving object's transform must not mirror (its determinant is negative)");
        for (int c = 0; c < 3; ++c)
            if (glm::vec3(k.to_world[c]) != glm::vec3(keys[0].to_world[c])) m.translation_only = false;
        m.parts.push_back(decompose(k.to_world));
    }
    for (std::size_t i = 1; i < m.parts.size(); ++i) {
        if (glm::dot(m.parts[i].rotation, m.parts[i - 1].rotation) < 0.0) m.parts[i].rotation = -m.parts[i].rotation;
        const double d = std::min(1.0, glm::dot(m.parts[i].rotation, m.parts[i - 1].rotation));
        m.angles.push_back(m.translation_only ? 0.0 : 2.0 * std::acos(d));
    }
    if (m.translation_only) m.inverse_linear = glm::inverse(glm::dmat3(glm::dmat4(keys[0].to_world)));
    m.keys = std::move(keys);
    return m;
}

Transform pose_at(const Motion& motion, float s) {
    const std::size_t segments = motion.keys.size() - 1;
    const double x = std::clamp(static_cast<double>(s), 0.0, 1.0) * static_cast<double>(segments);
    const std::size_t k = std::min(static_cast<std::size_t>(x), segments - 1);
    return pose_in_segment(motion, k, x - static_cast<double>(k));
}

bool keys_equal(const std::vector<Transform>& keys) {
    for (const Transform& k : keys)
        if (k.to_world != keys.front().to_world) return false;
    return true;
}

collision::Bounds3 motion_world_bounds(const Motion& motion, const collision::Bounds3& object_box, float s0, float s1) {
    if (object_box.empty()) return object_box;
    const std::size_t segments = motion.keys.size() - 1;
    const double x0 = std::clamp(static_cast<double>(s0), 0.0, 1.0) * static_cast<double>(segments);
    const double x1 = std::clamp(static_cast<double>(s1), 0.0, 1.0) * static_cast<double>(segments);
    collision::Bounds3 out;
    for (std::size_t k = 0; k < segments; ++k) {
        const double lo = std::max(x0, static_cast<double>(k)), hi = std::min(x1, static_cast<double>(k + 1));
        if (lo > hi) continue;
        out.extend(segment_bounds(motion, k, lo - static_cast<double>(k), hi - static_cast<double>(k), object_box));
    }
    return out;
}

std::vector<collision::Bounds3> motion_step_bounds(const Motion& motion, const collision::Bounds3& object_box, int steps) {
    const std::size_t segments = motion.keys.size() - 1;
    const std::size_t per_segment = (static_cast<std::size_t>(steps) - 1) / segments;
    const double h = 1.0 / static_cast<double>(per_segment);
    std::vector<float> growth(static_cast<std::size_t>(steps), 0.0f);
    for (std::size_t k = 0; k < segments; ++k) {
        const PieceGrowth g = piece_growth(motion, k, h, object_box);
        const float by = g.accel * 0.125f * (1.0f + collision::gamma(2)) + g.pad;
        for (std::size_t j = 0; j < per_segment; ++j) {
            float& a = growth[k * per_segment + j];
            float& b = growth[k * per_segment + j + 1];
            a = std::max(a, by);
            b = std::max(b, by);
        }
    }
    std::vector<collision::Bounds3> out;
    for (int j = 0; j < steps; ++j) {
        const std::size_t k = std::min(static_cast<std::size_t>(j) / per_segment, segments - 1);
        const double f = static_cast<double>(static_cast<std::size_t>(j) - k * per_segment) * h;
        collision::Bounds3 b = grown(world_bounds(pose_in_segment(motion, k, f), object_box), growth[static_cast<std::size_t>(j)]);
        for (int a = 0; a < 3; ++a) {
            b.lo[a] = collision::next_float_down(b.lo[a]);
            b.hi[a] = collision::next_float_up(b.hi[a]);
        }
        out.push_back(b);
    }
    return out;
}

int motion_time_steps(const Motion& motion) {
    const int segments = static_cast<int>(motion.keys.size()) - 1;
    bool rotates = false;
    for (double a : motion.angles) rotates = rotates || a > 0.0;
    if (!rotates) return segments + 1;
    const int per_segment = std::max(1, std::min(kRotationSteps, (kMaxMotionKeys - 1) / segments));
    return segments * per_segment + 1;
}

}  // namespace sweeptrace
