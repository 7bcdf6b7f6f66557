#include "raytracer/image/flip_color.hpp"

#include <cmath>

#include <glm/matrix.hpp>

namespace sweeptrace::flip_color {
namespace {

// XYZ of chromaticity (x, y) at Y = 1.
glm::dvec3 xyz_of(double x, double y) { return {x / y, 1.0, (1.0 - x - y) / y}; }

// Columns: the XYZ of each primary, scaled so the three sum to the white point.
glm::dmat3 derive_rgb_to_xyz() {
    const glm::dmat3 primaries(xyz_of(0.64, 0.33), xyz_of(0.30, 0.60), xyz_of(0.15, 0.06));
    const glm::dvec3 scale = glm::inverse(primaries) * xyz_of(0.31271, 0.32902);
    return glm::dmat3(primaries[0] * scale.x, primaries[1] * scale.y, primaries[2] * scale.z);
}

double lab_f(double t) {
    constexpr double d = 6.0 / 29.0;
    return t > d * d * d ? std::cbrt(t) : t / (3.0 * d * d) + 4.0 / 29.0;
}

}  // namespace

const glm::dmat3& rgb_to_xyz_matrix() {
    static const glm::dmat3 m = derive_rgb_to_xyz();
    return m;
}

const glm::dmat3& xyz_to_rgb_matrix() {
    static const glm::dmat3 m = glm::inverse(rgb_to_xyz_matrix());
    return m;
}

glm::dvec3 reference_white() { return rgb_to_xyz_matrix() * glm::dvec3(1.0); }

glm::dvec3 linear_rgb_to_xyz(const glm::dvec3& rgb) { return rgb_to_xyz_matrix() * rgb; }
glm::dvec3 xyz_to_linear_rgb(const glm::dvec3& xyz) { return xyz_to_rgb_matrix() * xyz; }

glm::dvec3 xyz_to_ycxcz(const glm::dvec3& xyz) {
    const glm::dvec3 r = xyz / reference_white();
    return {116.0 * r.y - 16.0, 500.0 * (r.x - r.y), 200.0 * (r.y - r.z)};
}

glm::dvec3 ycxcz_to_xyz(const glm::dvec3& ycxcz) {
    const double y = (ycxcz.x + 16.0) / 116.0;
    const glm::dvec3 r(ycxcz.y / 500.0 + y, y, y - ycxcz.z / 200.0);
    return r * reference_white();
}

glm::dvec3 xyz_to_lab(const glm::dvec3& xyz) {
    const glm::dvec3 r = xyz / reference_white();
    const double fx = lab_f(r.x), fy = lab_f(r.y), fz = lab_f(r.z);
    return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

glm::dvec3 hunt_adjust(const glm::dvec3& lab) {
    const double s = 0.01 * lab.x;
    return {lab.x, s * lab.y, s * lab.z};
}

double hyab(const glm::dvec3& p, const glm::dvec3& q) {
    const double da = p.y - q.y, db = p.z - q.z;
    return std::abs(p.x - q.x) + std::sqrt(da * da + db * db);
}

}  // namespace sweeptrace::flip_color
