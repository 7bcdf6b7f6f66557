#include "raytracer/scene/pbrt/pbrt_transform.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace sweeptrace::pbrt {

glm::dmat4 matrix_from_pbrt(const double* m) {
    glm::dmat4 r(1.0);
    for (int c = 0; c < 4; ++c)
        for (int row = 0; row < 4; ++row) r[c][row] = m[c * 4 + row];
    return r;
}

std::optional<glm::dmat4> look_at(const glm::dvec3& eye, const glm::dvec3& look, const glm::dvec3& up) {
    const glm::dvec3 d = look - eye;
    if (glm::length(d) == 0.0 || glm::length(up) == 0.0) return std::nullopt;
    const glm::dvec3 dir = glm::normalize(d);
    const glm::dvec3 c = glm::cross(glm::normalize(up), dir);
    if (glm::length(c) < 1e-9) return std::nullopt;
    const glm::dvec3 right = glm::normalize(c);
    const glm::dvec3 new_up = glm::cross(dir, right);
    glm::dmat4 world_from_camera(1.0);
    world_from_camera[0] = glm::dvec4(right, 0.0);
    world_from_camera[1] = glm::dvec4(new_up, 0.0);
    world_from_camera[2] = glm::dvec4(dir, 0.0);
    world_from_camera[3] = glm::dvec4(eye, 1.0);
    return glm::inverse(world_from_camera);
}

double det3(const glm::dmat4& m) { return glm::determinant(glm::dmat3(m)); }

namespace {

// Symmetric 3x3 a = v diag(w) v^T by cyclic Jacobi rotations; v's columns are the eigenvectors.
void jacobi_eigen(glm::dmat3 a, glm::dmat3& v, glm::dvec3& w) {
    v = glm::dmat3(1.0);
    for (int sweep = 0; sweep < 60; ++sweep) {
        const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        const double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if (off <= 1e-32 * diag || off == 0.0) break;
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (a[q][p] == 0.0) continue;
                const double theta = (a[q][q] - a[p][p]) / (2.0 * a[q][p]);
                const double t = (theta >= 0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
                glm::dmat3 j(1.0);  // glm is column-major: j[col][row]
                j[p][p] = c;
                j[q][q] = c;
                j[q][p] = s;
                j[p][q] = -s;
                a = glm::transpose(j) * a * j;
                v = v * j;
            }
    }
    w = glm::dvec3(a[0][0], a[1][1], a[2][2]);
}

}  // namespace

std::optional<AffineSteps> split_affine(const glm::dmat4& m) {
    const glm::dmat3 a(m);
    if (!(glm::determinant(a) > 0.0)) return std::nullopt;
    AffineSteps s;
    s.translation = glm::dvec3(m[3]);
    glm::dmat3 v;
    glm::dvec3 w;
    jacobi_eigen(glm::transpose(a) * a, v, w);
    if (glm::determinant(v) < 0.0) v[2] = -v[2];
    const double largest = std::max({w.x, w.y, w.z});
    glm::dmat3 u;
    for (int i = 0; i < 3; ++i) {
        if (!(w[i] > 1e-24 * largest)) return std::nullopt;
        s.scale[i] = std::sqrt(w[i]);
        u[i] = a * v[i] / s.scale[i];
    }
    // Re-orthonormalise u (Gram-Schmidt): its columns are orthogonal up to rounding already.
    u[0] = glm::normalize(u[0]);
    u[1] = glm::normalize(u[1] - glm::dot(u[1], u[0]) * u[0]);
    u[2] = glm::cross(u[0], u[1]);
    s.rotation = u;
    s.pre_rotation = glm::transpose(v);
    return s;
}

void axis_angle(const glm::dmat3& r, glm::dvec3& axis, double& degrees) {
    // Unit quaternion by the largest of its four squared components (Shepperd), then 2 atan2.
    const double tr = r[0][0] + r[1][1] + r[2][2];
    double q[4];  // w, x, y, z
    if (tr >= r[0][0] && tr >= r[1][1] && tr >= r[2][2]) {
        const double s = std::sqrt(1.0 + tr) * 2.0;
        q[0] = 0.25 * s;
        q[1] = (r[1][2] - r[2][1]) / s;
        q[2] = (r[2][0] - r[0][2]) / s;
        q[3] = (r[0][1] - r[1][0]) / s;
    } else if (r[0][0] >= r[1][1] && r[0][0] >= r[2][2]) {
        const double s = std::sqrt(1.0 + r[0][0] - r[1][1] - r[2][2]) * 2.0;
        q[0] = (r[1][2] - r[2][1]) / s;
        q[1] = 0.25 * s;
        q[2] = (r[1][0] + r[0][1]) / s;
        q[3] = (r[2][0] + r[0][2]) / s;
    } else if (r[1][1] >= r[2][2]) {
        const double s = std::sqrt(1.0 + r[1][1] - r[0][0] - r[2][2]) * 2.0;
        q[0] = (r[2][0] - r[0][2]) / s;
        q[1] = (r[1][0] + r[0][1]) / s;
        q[2] = 0.25 * s;
        q[3] = (r[2][1] + r[1][2]) / s;
    } else {
        const double s = std::sqrt(1.0 + r[2][2] - r[0][0] - r[1][1]) * 2.0;
        q[0] = (r[0][1] - r[1][0]) / s;
        q[1] = (r[2][0] + r[0][2]) / s;
        q[2] = (r[2][1] + r[1][2]) / s;
        q[3] = 0.25 * s;
    }
    const glm::dvec3 xyz(q[1], q[2], q[3]);
    const double len = glm::length(xyz);
    if (len == 0.0) {
        axis = glm::dvec3(0.0, 1.0, 0.0);
        degrees = 0.0;
        return;
    }
    axis = xyz / len;
    degrees = 2.0 * std::atan2(len, q[0]) * 180.0 / 3.14159265358979323846;
}

}  // namespace sweeptrace::pbrt
