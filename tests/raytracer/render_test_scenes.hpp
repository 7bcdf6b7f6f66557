#pragma once
// Small scenes built in code and a brute-force Accel over them (spheres and quads, untransformed,
// intersected in double precision), so the renderer's tests depend on neither the scene loader
// nor the BVH.
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <variant>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "collision/float_error.hpp"
#include "raytracer/accel/accel.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace::test {

class DoublePrecisionAccel final : public Accel {
public:
    explicit DoublePrecisionAccel(const Scene& scene) : scene_(scene) {
        for (const Object& o : scene.objects) {
            if (!o.transform.identity) throw std::invalid_argument("DoublePrecisionAccel: transforms not supported");
            if (!std::holds_alternative<collision::Sphere>(o.shape) && !std::holds_alternative<collision::Quad>(o.shape))
                throw std::invalid_argument("DoublePrecisionAccel: spheres and quads only");
        }
    }

    bool intersect(const collision::Ray& ray, SurfaceHit& hit) const override {
        bool found = false;
        double tmax = ray.tmax;
        for (std::uint32_t i = 0; i < scene_.objects.size(); ++i) {
            SurfaceHit h;
            if (hit_object(ray, i, tmax, h)) {
                found = true;
                tmax = h.t;
                hit = h;
            }
        }
        return found;
    }
    bool occluded(const collision::Ray& ray) const override {
        SurfaceHit h;
        for (std::uint32_t i = 0; i < scene_.objects.size(); ++i)
            if (hit_object(ray, i, ray.tmax, h)) return true;
        return false;
    }
    std::size_t memory_bytes() const override { return 0; }
    std::string name() const override { return "brute force (test)"; }

private:
    // In double: the float inputs are exact doubles, so t and the point are accurate to a few
    // double ulps; the reported float point is the rounded exact point, its error bound a few
    // float ulps of the coordinates involved.
    bool hit_object(const collision::Ray& ray, std::uint32_t i, double tmax, SurfaceHit& h) const {
        const glm::dvec3 o(ray.origin), d(ray.dir);
        const Object& obj = scene_.objects[i];
        double t;
        glm::dvec3 n, p;
        glm::vec3 err;
        if (const auto* s = std::get_if<collision::Sphere>(&obj.shape)) {
            const glm::dvec3 c(s->center);
            const double r = s->radius;
            const glm::dvec3 oc = o - c;
            const double a = glm::dot(d, d), b = glm::dot(oc, d);
            const glm::dvec3 closest = oc - (b / a) * d;  // Hearn-Baker: no cancellation in disc
            const double disc = r * r - glm::dot(closest, closest);
            if (disc < 0) return false;
            const double q = -b - std::copysign(std::sqrt(a * disc), b);
            double t0 = q / a, t1 = (glm::dot(oc, oc) - r * r) / q;  // roots q/a and c/q
            if (t0 > t1) std::swap(t0, t1);
            t = t0 > ray.tmin ? t0 : t1;
            if (!(t > ray.tmin && t < tmax)) return false;
            n = glm::normalize(o + t * d - c);
            p = c + r * n;
            err = collision::gamma(4) * (glm::abs(glm::vec3(c)) + glm::vec3(float(r)));
        } else {
            const auto& qd = std::get<collision::Quad>(obj.shape);
            const glm::dvec3 c(qd.corner), eu(qd.edge_u), ev(qd.edge_v);
            const glm::dvec3 nn = glm::cross(eu, ev);
            const double dn = glm::dot(d, nn);
            if (dn == 0) return false;
            t = glm::dot(c - o, nn) / dn;
            if (!(t > ray.tmin && t < tmax)) return false;
            p = o + t * d;
            const glm::dvec3 w = p - c;
            const double nn2 = glm::dot(nn, nn);
            const double su = glm::dot(glm::cross(w, ev), nn) / nn2, sv = glm::dot(glm::cross(eu, w), nn) / nn2;
            if (su < 0 || su > 1 || sv < 0 || sv > 1) return false;
            n = glm::normalize(nn);
            err = collision::gamma(4) * (glm::abs(qd.corner) + glm::abs(qd.edge_u) + glm::abs(qd.edge_v));
        }
        h.t = static_cast<float>(t);
        h.point = glm::vec3(p);
        h.point_error = err;
        h.normal = glm::vec3(n);
        h.shading_normal = h.normal;
        h.object = i;
        return true;
    }

    const Scene& scene_;
};

inline std::uint32_t add_material(Scene& s, Material m) {
    s.materials.push_back(std::move(m));
    return static_cast<std::uint32_t>(s.materials.size() - 1);
}

inline Material diffuse(glm::vec3 albedo, glm::vec3 emission = glm::vec3(0.0f)) {
    Material m;
    m.type = Material::Type::Diffuse;
    m.albedo = albedo;
    m.emission = emission;
    return m;
}

inline void add_object(Scene& s, Shape shape, std::uint32_t material) {
    Object o;
    o.shape = shape;
    o.material = material;
    s.objects.push_back(std::move(o));
}

// A small open box: grey floor and back wall, a diffuse sphere and a metal sphere, lit by a quad
// light facing down and a small emissive sphere; black background so all light is from them.
inline Scene two_light_scene(int width, int height) {
    Scene s;
    s.film.width = width;
    s.film.height = height;
    s.camera.position = {0.0f, 1.0f, 4.5f};
    s.camera.look_at = {0.0f, 0.8f, 0.0f};
    s.camera.vfov_degrees = 45.0f;
    const auto grey = add_material(s, diffuse(glm::vec3(0.7f)));
    const auto red = add_material(s, diffuse({0.8f, 0.3f, 0.2f}));
    Material metal;
    metal.type = Material::Type::Metal;
    metal.albedo = {0.9f, 0.8f, 0.6f};
    metal.roughness = 0.4f;
    const auto gold = add_material(s, metal);
    const auto quad_light = add_material(s, diffuse(glm::vec3(0.0f), glm::vec3(1.5f, 1.5f, 1.2f)));
    Material bulb;
    bulb.type = Material::Type::Emissive;
    bulb.emission = {3.0f, 1.5f, 0.8f};
    const auto sphere_light = add_material(s, bulb);
    add_object(s, collision::Quad{{-3.0f, 0.0f, 3.0f}, {6.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -6.0f}}, grey);  // floor, up
    add_object(s, collision::Quad{{-3.0f, 0.0f, -2.0f}, {6.0f, 0.0f, 0.0f}, {0.0f, 4.0f, 0.0f}}, grey);  // back wall
    add_object(s, collision::Sphere{{-0.7f, 0.6f, 0.0f}, 0.6f}, red);
    add_object(s, collision::Sphere{{0.8f, 0.5f, 0.4f}, 0.5f}, gold);
    // Both lights large and near, so that light and BSDF sampling densities are comparable over
    // much of the image and the MIS weights matter (an error in them shows).
    // Quad light normal edge_u x edge_v = (1,0,0) x (0,0,1) = (0,-1,0): facing down.
    add_object(s, collision::Quad{{-1.2f, 2.2f, -1.2f}, {2.4f, 0.0f, 0.0f}, {0.0f, 0.0f, 2.4f}}, quad_light);
    add_object(s, collision::Sphere{{1.7f, 1.6f, -0.9f}, 0.4f}, sphere_light);
    return s;
}

}  // namespace sweeptrace::test
