#include "raytracer/render/lights.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/matrix.hpp>

#include "collision/float_error.hpp"
#include "raytracer/render/bsdf.hpp"
#include "raytracer/render/sampling.hpp"

namespace sweeptrace {

namespace {

using collision::gamma;

glm::vec3 transform_point(const glm::mat4& m, const glm::vec3& p) { return glm::vec3(m * glm::vec4(p, 1.0f)); }

glm::mat3 abs_mat(const glm::mat3& m) {
    glm::mat3 a;
    for (int c = 0; c < 3; ++c) a[c] = glm::abs(m[c]);
    return a;
}

// Is the linear part s * R (R orthogonal)? L^T L must then be s^2 I. Each entry of the float
// product carries a few ulps of error relative to s^2, and transforms composed from rotations in
// float carry a few more; 64 ulps accepts those and still rejects any deliberate non-uniform
// scale. A shape accepted with a residual of that size is sampled with a cone off by a relative
// 1e-5, far below noise.
bool is_similarity(const glm::mat3& l, float& scale) {
    const glm::mat3 g = glm::transpose(l) * l;
    const float s2 = (g[0][0] + g[1][1] + g[2][2]) / 3.0f;
    const float tol = 64.0f * std::numeric_limits<float>::epsilon() * s2;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (std::abs(g[c][r] - (c == r ? s2 : 0.0f)) > tol) return false;
    scale = std::sqrt(s2);
    return true;
}

// Rounding bound of p_w = L p + t computed in float from p (itself off by `err`): each output
// coordinate is a sum of three products and a translation, gamma(3) relative to the sum of
// magnitudes (Higham), plus the input error carried through |L|.
glm::vec3 affine_error(const glm::mat3& l, const glm::vec3& t, const glm::vec3& p, const glm::vec3& err) {
    const glm::mat3 al = abs_mat(l);
    return gamma(3) * (al * glm::abs(p) + glm::abs(t)) + al * err;
}

// The cone a sphere (centre c, radius r) subtends from p, or false when p is inside it or on it
// (`on_sphere`: p is a hit point of this sphere). Both sample() and pdf() decide cone-or-area
// through this one function, so they always agree. A point on the sphere must not be classified
// by |p - c|^2 > r^2: its rounding error (gamma(7) r per axis) decides that comparison, and a
// point rounded outside gets a cone of half-angle ~90 degrees whose visible cap is the point
// itself, so every sample lands at p and the MIS density of the far wall is the cone's 1/(2 pi)
// though the cone never produces it: measured inside a unit sphere, 34 % of hit points fell
// "outside" and their one-bounce estimate was 0.31 instead of 0.5.
struct Cone {
    float dc2 = 0.0f, sin2_max = 0.0f, omc = 0.0f;  // |p - c|^2, sin^2(theta_max), 1 - cos(theta_max)
};
bool cone_from(const glm::vec3& c, float r, const glm::vec3& p, bool on_sphere, Cone& cone) {
    if (on_sphere) return false;
    const glm::vec3 to_p = p - c;
    cone.dc2 = glm::dot(to_p, to_p);
    const float r2 = r * r;
    if (!(cone.dc2 > r2)) return false;
    cone.sin2_max = r2 / cone.dc2;
    const float cos_max = std::sqrt(std::max(0.0f, 1.0f - cone.sin2_max));
    cone.omc = cone.sin2_max / (1.0f + cos_max);  // 1 - cos, without cancellation for small cones
    return true;
}

}  // namespace

LightSet::LightSet(const Scene& scene, PlantedDefect defect)
    : scene_(&scene),
      normal_sign_(defect == PlantedDefect::FlippedNormals ? -1.0f : 1.0f),
      light_of_object_(scene.objects.size(), -1) {
    std::vector<float> weights;
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        const Object& obj = scene.objects[i];
        const Material& mat = scene.materials[obj.material];
        const float lum = luminance(mat.emission);
        if (!(lum > 0.0f)) continue;
        const glm::mat4& m = obj.transform.to_world;
        const glm::mat3 lin(m);
        const glm::vec3 t(m[3]);
        Light l;
        l.object = i;
        l.material = &mat;
        l.linear = lin;
        l.normal_to_world = obj.transform.normal_to_world;
        l.inv_abs_det = 1.0f / std::abs(glm::determinant(lin));
        float area = 0.0f;
        std::visit(
            [&](const auto& shape) {
                using S = std::decay_t<decltype(shape)>;
                if constexpr (std::is_same_v<S, collision::Sphere>) {
                    float s = 1.0f;
                    if (is_similarity(lin, s)) {
                        l.kind = Kind::SphereCone;
                        l.origin = transform_point(m, shape.center);
                        l.radius = s * shape.radius;
                        area = 4.0f * kPi * l.radius * l.radius;
                        l.area_pdf = 1.0f / area;
                    } else {
                        l.kind = Kind::Surface;
                        l.origin = t;
                        const float ao = 4.0f * kPi * shape.radius * shape.radius;
                        l.area_pdf = 1.0f / ao;
                        area = ao * std::cbrt(1.0f / (l.inv_abs_det * l.inv_abs_det));
                    }
                } else if constexpr (std::is_same_v<S, collision::Quad>) {
                    l.kind = Kind::Parallelogram;
                    l.origin = transform_point(m, shape.corner);
                    l.edge_u = lin * shape.edge_u;
                    l.edge_v = lin * shape.edge_v;
                    l.normal = glm::normalize(l.normal_to_world * glm::cross(shape.edge_u, shape.edge_v));
                    area = glm::length(glm::cross(l.edge_u, l.edge_v));
                    l.area_pdf = 1.0f / area;
                } else if constexpr (std::is_same_v<S, collision::Triangle>) {
                    l.kind = Kind::Triangle;
                    l.origin = transform_point(m, shape.a);
                    l.edge_u = transform_point(m, shape.b) - l.origin;
                    l.edge_v = transform_point(m, shape.c) - l.origin;
                    l.normal = glm::normalize(l.normal_to_world * glm::cross(shape.b - shape.a, shape.c - shape.a));
                    area = 0.5f * glm::length(glm::cross(l.edge_u, l.edge_v));
                    l.area_pdf = 1.0f / area;
                } else if constexpr (std::is_same_v<S, collision::Disk>) {
                    // The unit disk's image is an ellipse c + x U + y V with U, V the images of
                    // two orthogonal radii; uniform on the disk stays uniform on the ellipse.
                    l.kind = Kind::Ellipse;
                    const Frame f(glm::normalize(shape.normal));
                    l.origin = transform_point(m, shape.center);
                    l.edge_u = lin * (shape.radius * f.s);
                    l.edge_v = lin * (shape.radius * f.t);
                    l.normal = glm::normalize(l.normal_to_world * f.n);
                    area = kPi * glm::length(glm::cross(l.edge_u, l.edge_v));
                    l.area_pdf = 1.0f / area;
                } else if constexpr (std::is_same_v<S, collision::Ellipsoid>) {
                    // Sampled as the unit sphere under L diag(radii), translated to the centre.
                    l.kind = Kind::Surface;
                    l.origin = transform_point(m, shape.center);
                    l.linear = lin * glm::mat3(glm::vec3(shape.radii.x, 0, 0), glm::vec3(0, shape.radii.y, 0),
                                               glm::vec3(0, 0, shape.radii.z));
                    l.normal_to_world = glm::inverseTranspose(l.linear);
                    l.inv_abs_det = 1.0f / std::abs(glm::determinant(l.linear));
                    l.area_pdf = 1.0f / (4.0f * kPi);
                    area = 4.0f * kPi * std::cbrt(1.0f / (l.inv_abs_det * l.inv_abs_det));
                } else if constexpr (std::is_same_v<S, collision::Aabb>) {
                    l.kind = Kind::Surface;
                    l.origin = t;
                    const glm::vec3 z = shape.size;
                    const float ao = 2.0f * (z.y * z.z + z.x * z.z + z.x * z.y);
                    l.area_pdf = 1.0f / ao;
                    area = ao * std::cbrt(1.0f / (l.inv_abs_det * l.inv_abs_det));
                } else if constexpr (std::is_same_v<S, collision::Cylinder>) {
                    l.kind = Kind::Surface;
                    l.origin = t;
                    const float ao = 2.0f * kPi * shape.radius * (shape.radius + shape.height);
                    l.area_pdf = 1.0f / ao;
                    area = ao * std::cbrt(1.0f / (l.inv_abs_det * l.inv_abs_det));
                } else if constexpr (std::is_same_v<S, collision::Capsule>) {
                    l.kind = Kind::Surface;
                    l.origin = t;
                    const float ao = 2.0f * kPi * shape.radius * (2.0f * shape.radius + shape.height);
                    l.area_pdf = 1.0f / ao;
                    area = ao * std::cbrt(1.0f / (l.inv_abs_det * l.inv_abs_det));
                } else if constexpr (std::is_same_v<S, MeshInstance>) {
                    l.kind = Kind::Mesh;
                    l.origin = t;
                    const collision::TriangleMesh& tm = scene.meshes[shape.mesh].triangles;
                    l.first_triangle = static_cast<std::uint32_t>(triangle_cdf_.size());
                    l.triangle_count = static_cast<std::uint32_t>(tm.triangle_count());
                    double sum = 0.0;
                    for (std::size_t k = 0; k < tm.triangle_count(); ++k) {
                        const collision::Triangle tri = tm.triangle(k);
                        sum += 0.5 * glm::length(glm::cross(lin * (tri.b - tri.a), lin * (tri.c - tri.a)));
                        triangle_cdf_.push_back(static_cast<float>(sum));
                    }
                    area = static_cast<float>(sum);
                    l.area_pdf = 1.0f / area;
                }
            },
            obj.shape);
        const float weight = lum * area * (mat.two_sided_emission ? 2.0f : 1.0f);
        if (!(weight > 0.0f) || !std::isfinite(weight) || !(l.area_pdf > 0.0f) || !std::isfinite(l.area_pdf)) continue;
        light_of_object_[i] = static_cast<std::int32_t>(lights_.size());
        lights_.push_back(l);
        weights.push_back(weight);
    }
    double total = 0.0;
    for (float w : weights) total += w;
    double running = 0.0;
    for (std::size_t k = 0; k < lights_.size(); ++k) {
        lights_[k].probability = static_cast<float>(weights[k] / total);
        running += weights[k];
        cdf_.push_back(static_cast<float>(running / total));
    }
    if (!cdf_.empty()) cdf_.back() = 1.0f;
}

// Nanson's formula: dA_world = |det L| / |L^T n| dA_object for world normal n.
float LightSet::surface_area_pdf(const Light& l, const glm::vec3& n) {
    return l.area_pdf * glm::length(glm::transpose(l.linear) * n) * l.inv_abs_det;
}

float LightSet::selection_probability(std::uint32_t object) const {
    return is_light(object) ? lights_[static_cast<std::size_t>(light_of_object_[object])].probability : 0.0f;
}

bool LightSet::sample_surface(const Light& l, float u_part, float u1, float u2, glm::vec3& p, glm::vec3& n,
                              glm::vec3& err) const {
    const Shape& shape = scene_->objects[l.object].shape;
    if (const auto* s = std::get_if<collision::Sphere>(&shape)) {
        n = uniform_sphere(u1, u2);
        p = s->center + s->radius * n;
        err = gamma(3) * (glm::abs(s->center) + glm::vec3(s->radius));
    } else if (std::get_if<collision::Ellipsoid>(&shape)) {
        n = uniform_sphere(u1, u2);  // unit sphere: the radii are folded into l.linear
        p = n;
        err = glm::vec3(gamma(3));
    } else if (const auto* b = std::get_if<collision::Aabb>(&shape)) {
        // A face chosen by area, then uniform on it.
        const glm::vec3 z = b->size;
        const float areas[3] = {z.y * z.z, z.x * z.z, z.x * z.y};
        float x = u_part * (areas[0] + areas[1] + areas[2]);
        int axis = 0;
        while (axis < 2 && x >= areas[axis]) x -= areas[axis++];
        const float side = (x < 0.5f * areas[axis]) ? -1.0f : 1.0f;
        const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
        glm::vec3 local(0.0f);
        local[axis] = 0.5f * side * z[axis];
        local[a1] = (u1 - 0.5f) * z[a1];
        local[a2] = (u2 - 0.5f) * z[a2];
        p = b->center + local;
        n = glm::vec3(0.0f);
        n[axis] = side;
        err = gamma(2) * (glm::abs(b->center) + z);
    } else if (const auto* c = std::get_if<collision::Cylinder>(&shape)) {
        const float side_area = c->height, cap_area = 0.5f * c->radius;  // both divided by 2 pi r
        const float x = u_part * (side_area + 2.0f * cap_area);
        if (x < side_area) {
            const float phi = 2.0f * kPi * u2;
            n = glm::vec3(std::cos(phi), 0.0f, std::sin(phi));
            p = c->center + glm::vec3(c->radius * n.x, (u1 - 0.5f) * c->height, c->radius * n.z);
        } else {
            const float sign = (x < side_area + cap_area) ? 1.0f : -1.0f;
            const glm::vec2 d = c->radius * concentric_disk(u1, u2);
            n = glm::vec3(0.0f, sign, 0.0f);
            p = c->center + glm::vec3(d.x, sign * 0.5f * c->height, d.y);
        }
        err = gamma(4) * (glm::abs(c->center) + glm::vec3(c->radius + c->height));
    } else if (const auto* c = std::get_if<collision::Capsule>(&shape)) {
        const float side_area = c->height, sphere_area = 2.0f * c->radius;  // both divided by 2 pi r
        if (u_part * (side_area + sphere_area) < side_area) {
            const float phi = 2.0f * kPi * u2;
            n = glm::vec3(std::cos(phi), 0.0f, std::sin(phi));
            p = c->center + glm::vec3(c->radius * n.x, (u1 - 0.5f) * c->height, c->radius * n.z);
        } else {
            n = uniform_sphere(u1, u2);
            const float cap = n.y >= 0.0f ? 0.5f * c->height : -0.5f * c->height;
            p = c->center + glm::vec3(0.0f, cap, 0.0f) + c->radius * n;
        }
        err = gamma(4) * (glm::abs(c->center) + glm::vec3(c->radius + c->height));
    } else {
        return false;
    }
    return true;
}

bool LightSet::sample(const glm::vec3& p, std::uint32_t p_object, float u_select, float u_part, float u1, float u2, LightSample& out) const {
    if (lights_.empty()) return false;
    const auto it = std::upper_bound(cdf_.begin(), cdf_.end(), u_select);
    const Light& l = lights_[static_cast<std::size_t>(std::min<std::ptrdiff_t>(it - cdf_.begin(), cdf_.size() - 1))];

    glm::vec3 q, n, err;
    float area_pdf = l.area_pdf;
    switch (l.kind) {
        case Kind::SphereCone: {
            Cone cone;
            if (cone_from(l.origin, l.radius, p, p_object == l.object, cone)) {
                // Cone sampling (pbrt-v3 §14.2): a direction in the subtended cone, then the
                // point where it first meets the sphere, found through the angle at the centre.
                const float dc = std::sqrt(cone.dc2);
                const float sin2_max = cone.sin2_max;
                const float omc = cone.omc;
                const glm::vec3 to_p = p - l.origin;
                const glm::vec3 d = uniform_cone(u1, u2, omc);
                const float sin2_t = d.x * d.x + d.y * d.y;
                const float cos_t = d.z;
                // cos(alpha) in pbrt-v4's form (§6.2.4), free of the cancellation that the law of
                // cosines suffers for small, far lights.
                const float sin_max = std::sqrt(sin2_max);
                const float cos_a = std::clamp(
                    sin2_t / sin_max + cos_t * std::sqrt(std::max(0.0f, 1.0f - sin2_t / sin2_max)), -1.0f, 1.0f);
                const float sin_a = std::sqrt(std::max(0.0f, 1.0f - cos_a * cos_a));
                const float sin_t = std::sqrt(sin2_t);
                // In a frame whose z points from the centre toward p, the point's normal has polar
                // angle alpha; its azimuth is uniform like the direction's (any fixed relation
                // gives the same distribution; this one puts it where the direction meets it).
                const Frame f(to_p / dc);
                n = sin_t > 0.0f ? f.to_world(glm::vec3(sin_a * d.x / sin_t, sin_a * d.y / sin_t, cos_a)) : f.n;
                q = l.origin + l.radius * n;
                err = gamma(5) * (glm::abs(l.origin) + glm::vec3(l.radius));
                const glm::vec3 w = q - p;
                out.distance = glm::length(w);
                if (!(out.distance > 0.0f)) return false;
                out.wi = w / out.distance;
                out.pdf = l.probability * uniform_cone_pdf(omc);
                out.point = q;
                out.point_error = err;
                out.normal = normal_sign_ * n;
                out.radiance = emitted_radiance(*l.material, out.normal, -out.wi);
                return out.pdf > 0.0f && std::isfinite(out.pdf) && luminance(out.radiance) > 0.0f;
            }
            n = uniform_sphere(u1, u2);
            q = l.origin + l.radius * n;
            err = gamma(5) * (glm::abs(l.origin) + glm::vec3(l.radius));
            break;
        }
        case Kind::Parallelogram:
            q = l.origin + u1 * l.edge_u + u2 * l.edge_v;
            n = l.normal;
            err = gamma(3) * (glm::abs(l.origin) + glm::abs(l.edge_u) + glm::abs(l.edge_v));
            break;
        case Kind::Triangle: {
            const glm::vec2 b = uniform_triangle(u1, u2);
            // Barycentrics (b0, b1) of a and b: point = a + b1 (b - a) + (1 - b0 - b1) (c - a).
            q = l.origin + b.y * l.edge_u + (1.0f - b.x - b.y) * l.edge_v;
            n = l.normal;
            err = gamma(4) * (glm::abs(l.origin) + glm::abs(l.edge_u) + glm::abs(l.edge_v));
            break;
        }
        case Kind::Ellipse: {
            const glm::vec2 d = concentric_disk(u1, u2);
            q = l.origin + d.x * l.edge_u + d.y * l.edge_v;
            n = l.normal;
            err = gamma(3) * (glm::abs(l.origin) + glm::abs(l.edge_u) + glm::abs(l.edge_v));
            break;
        }
        case Kind::Surface: {
            glm::vec3 po, no, erro;
            if (!sample_surface(l, u_part, u1, u2, po, no, erro)) return false;
            q = l.linear * po + l.origin;
            err = affine_error(l.linear, l.origin, po, erro);
            n = glm::normalize(l.normal_to_world * no);
            area_pdf = surface_area_pdf(l, n);
            break;
        }
        case Kind::Mesh: {
            const float* first = triangle_cdf_.data() + l.first_triangle;
            const float* last = first + l.triangle_count;
            const float total = *(last - 1);
            const float* hit = std::upper_bound(first, last, u_part * total);
            const std::size_t k = static_cast<std::size_t>(std::min<std::ptrdiff_t>(hit - first, l.triangle_count - 1));
            const Object& obj = scene_->objects[l.object];
            const collision::Triangle tri =
                scene_->meshes[std::get<MeshInstance>(obj.shape).mesh].triangles.triangle(k);
            const glm::vec2 b = uniform_triangle(u1, u2);
            const glm::vec3 po = b.x * tri.a + b.y * tri.b + (1.0f - b.x - b.y) * tri.c;
            const glm::vec3 erro = gamma(4) * (glm::abs(tri.a) + glm::abs(tri.b) + glm::abs(tri.c));
            q = l.linear * po + l.origin;
            err = affine_error(l.linear, l.origin, po, erro);
            n = glm::normalize(l.normal_to_world * glm::cross(tri.b - tri.a, tri.c - tri.a));
            break;
        }
    }
    const glm::vec3 w = q - p;
    const float d2 = glm::dot(w, w);
    out.distance = std::sqrt(d2);
    if (!(out.distance > 0.0f)) return false;
    out.wi = w / out.distance;
    const float cos_l = std::abs(glm::dot(n, out.wi));
    if (!(cos_l > 0.0f)) return false;
    out.pdf = l.probability * area_pdf * d2 / cos_l;
    out.point = q;
    out.point_error = err;
    out.normal = normal_sign_ * n;
    out.radiance = emitted_radiance(*l.material, out.normal, -out.wi);
    return std::isfinite(out.pdf) && luminance(out.radiance) > 0.0f;
}

float LightSet::pdf(const glm::vec3& p, std::uint32_t p_object, const SurfaceHit& hit) const {
    if (!is_light(hit.object)) return 0.0f;
    const Light& l = lights_[static_cast<std::size_t>(light_of_object_[hit.object])];
    float area_pdf = l.area_pdf;
    switch (l.kind) {
        case Kind::SphereCone: {
            Cone cone;
            if (cone_from(l.origin, l.radius, p, p_object == l.object, cone)) return l.probability * uniform_cone_pdf(cone.omc);
            break;
        }
        case Kind::Surface:
            area_pdf = surface_area_pdf(l, hit.normal);
            break;
        default:
            break;
    }
    const glm::vec3 w = hit.point - p;
    const float d2 = glm::dot(w, w);
    const float cos_l = std::abs(glm::dot(hit.normal, w)) / std::sqrt(d2);
    if (!(cos_l > 0.0f)) return 0.0f;
    return l.probability * area_pdf * d2 / cos_l;
}

}  // namespace sweeptrace
