#include "raytracer/render/camera.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "raytracer/render/sampling/sampling.hpp"

namespace sweeptrace {

CameraModel::CameraModel(const Camera& c, int width, int height, const FilterSpec& filter)
    : origin_(c.position), filter_(filter) {
    forward_ = glm::normalize(c.look_at - c.position);
    right_ = glm::normalize(glm::cross(forward_, c.up));
    up_ = glm::cross(right_, forward_);
    // A left-handed camera draws the mirror image: only the image's x turns round, up stays.
    if (c.left_handed) right_ = -right_;
    half_height_ = std::tan(0.5f * c.vfov_degrees * kPi / 180.0f);
    half_width_ = half_height_ * static_cast<float>(width) / static_cast<float>(height);
    inv_width_ = 1.0f / static_cast<float>(width);
    inv_height_ = 1.0f / static_cast<float>(height);
    lens_radius_ = 0.5f * c.aperture;
    focus_distance_ = c.focus_distance > 0.0f ? c.focus_distance : glm::length(c.look_at - c.position);
    near_clip_ = c.near_clip;
    shutter_ = c.shutter;
    shutter_open_ = c.shutter_open;
    shutter_close_ = c.shutter_close;
}

collision::Ray CameraModel::generate(float x, float y, float u1, float u2) const {
    const float sx = (2.0f * x * inv_width_ - 1.0f) * half_width_;
    const float sy = (1.0f - 2.0f * y * inv_height_) * half_height_;
    const glm::vec3 dir = forward_ + sx * right_ + sy * up_;  // through the plane at distance 1
    collision::Ray ray;
    if (lens_radius_ <= 0.0f) {
        // dir's component along forward_ is 1, so near_clip * dir lies on the clip plane (as
        // smallpt's cam.o + d * 140 does).
        ray.origin = origin_ + near_clip_ * dir;
        ray.dir = glm::normalize(dir);
        return ray;
    }
    // Thin lens: every ray through the same film point meets at the focus plane.
    const glm::vec3 focus = origin_ + focus_distance_ * dir;
    const glm::vec2 lens = lens_radius_ * concentric_disk(u1, u2);
    ray.origin = origin_ + lens.x * right_ + lens.y * up_;
    ray.dir = glm::normalize(focus - ray.origin);
    // The lens point lies on the plane through the eye, so the clip plane is near_clip / cos away.
    if (near_clip_ > 0.0f) ray.origin += (near_clip_ / glm::dot(ray.dir, forward_)) * ray.dir;
    return ray;
}

glm::vec3 CameraModel::camera_space(const glm::vec3& p) const {
    const glm::vec3 d = p - origin_;
    return {glm::dot(d, right_), glm::dot(d, up_), glm::dot(d, forward_)};
}

glm::vec3 CameraModel::lens_point(float u1, float u2) const {
    if (lens_radius_ <= 0.0f) return origin_;
    const glm::vec2 lens = lens_radius_ * concentric_disk(u1, u2);
    return origin_ + lens.x * right_ + lens.y * up_;
}

float CameraModel::lens_area() const { return lens_radius_ > 0.0f ? kPi * lens_radius_ * lens_radius_ : 1.0f; }

float CameraModel::direction_pdf(float cos_theta) const {
    if (!(cos_theta > 0.0f)) return 0.0f;
    const float area = 4.0f * half_width_ * half_height_;
    return 1.0f / (area * cos_theta * cos_theta * cos_theta);
}

// The inverse of generate(): the lens point lies on the plane through the eye, so the ray meets
// the focus plane at lens + d focus_distance / (d . forward), and the film point is where the
// pinhole through the eye would have aimed at that point.
bool CameraModel::film_position(const glm::vec3& lens, const glm::vec3& p, float margin, float& x, float& y) const {
    const glm::vec3 d = p - lens;
    const float along = glm::dot(d, forward_);
    if (!(along > near_clip_) || !(along > 0.0f)) return false;
    glm::vec3 on_plane = d / along;  // the direction scaled to the plane at distance 1
    if (lens_radius_ > 0.0f) on_plane = (lens + d * (focus_distance_ / along) - origin_) / focus_distance_;
    const float sx = glm::dot(on_plane, right_), sy = glm::dot(on_plane, up_);
    x = (sx / half_width_ + 1.0f) / (2.0f * inv_width_);
    y = (1.0f - sy / half_height_) / (2.0f * inv_height_);
    const float w = 1.0f / inv_width_, h = 1.0f / inv_height_;
    return x >= -margin && x < w + margin && y >= -margin && y < h + margin;
}

}  // namespace sweeptrace
