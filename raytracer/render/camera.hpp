#pragma once
// Primary rays: a pinhole, or a thin lens (aperture diameter > 0) focused at focus_distance
// (by default the distance to look_at). The vertical field of view spans the film's height; the
// horizontal extent follows the film's aspect ratio (width / height). Rays start on the plane
// near_clip ahead of the eye along the view axis (nothing between the eye and it is seen). Film
// positions within a pixel come from the pixel filter (film_offset). A left-handed camera
// (Camera::left_handed) runs the image's x the other way: the mirror image of the right-handed one.
#include <glm/vec3.hpp>

#include "collision/ray.hpp"
#include "raytracer/render/film/pixel_filter.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

class CameraModel {
public:
    CameraModel(const Camera& camera, int width, int height, const FilterSpec& filter = {});

    // Where in its pixel a camera sample lands, from two uniforms, and the weight it carries:
    // drawn from the film's reconstruction filter (render/film/pixel_filter.hpp). The default box
    // gives (u1, u2) themselves with weight 1.
    FilmOffset film_offset(float u1, float u2) const { return filter_.sample(u1, u2); }

    // The ray through film position (x, y) in pixels (x right, y down, (0, 0) the top-left corner
    // of the top-left pixel) and lens sample (u1, u2) in [0, 1)^2. Direction is unit length.
    collision::Ray generate(float x, float y, float u1, float u2) const;

    // With a shutter (Camera::shutter), the shutter fraction a camera sample is traced at, from
    // a uniform u in [0, 1): the time open + u (close - open) as the fraction of the shutter the
    // objects' keyframes are spaced over (geometry/motion.hpp), u itself; a shutter that opens and
    // closes at once gives 0 (every object at its first pose).
    bool has_shutter() const { return shutter_; }
    float shutter_fraction(float u) const { return shutter_open_ < shutter_close_ ? u : 0.0f; }

    // Camera importance, for light tracing (render/integrators/bdpt.cpp; pbrt-v4's We, PDF_We).
    // The lens point generate() starts from for lens sample (u1, u2): the eye for a pinhole.
    glm::vec3 lens_point(float u1, float u2) const;
    float lens_area() const;  // pi r^2; 1 for the pinhole, whose point is a delta
    const glm::vec3& forward() const { return forward_; }
    // World point p in the camera's frame (pbrt's camera space, the P feature of render --aovs):
    // x along the image's right, y up, z along the view axis from the eye (the depth).
    glm::vec3 camera_space(const glm::vec3& p) const;
    // Where on the film (pixels, as generate() takes them) the ray from lens point `lens` through
    // `p` lands; false when p is not seen from there: behind the near clip plane, or farther
    // than `margin` pixels outside the film (a wide pixel filter reaches that far).
    bool film_position(const glm::vec3& lens, const glm::vec3& p, float margin, float& x, float& y) const;
    // The solid-angle density with which generate() draws a direction at cos_theta to the view
    // axis from its lens point, film positions uniform over the film: 1 / (A cos^3 theta), A the
    // film's area on the plane at distance 1. The importance We = that / (lens_area cos theta).
    float direction_pdf(float cos_theta) const;
    float near_clip() const { return near_clip_; }
    const PixelFilter& filter() const { return filter_; }

private:
    glm::vec3 origin_;
    glm::vec3 right_, up_, forward_;  // orthonormal camera frame
    float half_width_ = 1.0f, half_height_ = 1.0f;  // image plane extent at distance 1
    float inv_width_ = 1.0f, inv_height_ = 1.0f;
    float lens_radius_ = 0.0f;
    float focus_distance_ = 1.0f;
    float near_clip_ = 0.0f;
    bool shutter_ = false;
    float shutter_open_ = 0.0f, shutter_close_ = 0.0f;
    PixelFilter filter_;
};

}  // namespace sweeptrace
