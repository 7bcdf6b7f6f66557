// Measuring your own ray-shape routine with sweeptrace's accuracy harness: register it, run the
// families, print the table. Here a textbook float ray-sphere test (the quadratic formula as
// written in most renderers), so the table shows what the robust routine fixes: grazing and far
// rays, and secondary rays that re-hit the sphere because the routine states no error bound.
// Built as build/examples/custom_intersector; run it with an optional ray count.
#include <cmath>
#include <cstdlib>
#include <iostream>

#include <glm/geometric.hpp>

#include "raytracer/accuracy/legend.hpp"
#include "raytracer/accuracy/report.hpp"
#include "raytracer/accuracy/routines.hpp"
#include "raytracer/accuracy/user_routines.hpp"

namespace {

// Contract of a routine: nearest hit with tmin < t < tmax (the exit when starting inside).
bool textbook_sphere(const collision::Ray& ray, const collision::Sphere& s, collision::RayHit& hit) {
    const glm::vec3 oc = ray.origin - s.center;
    const float a = glm::dot(ray.dir, ray.dir), b = glm::dot(oc, ray.dir);
    const float c = glm::dot(oc, oc) - s.radius * s.radius;
    const float disc = b * b - a * c;
    if (disc < 0.0f) return false;
    const float root = std::sqrt(disc);
    float t = (-b - root) / a;
    if (!(t > ray.tmin && t < ray.tmax)) t = (-b + root) / a;
    if (!(t > ray.tmin && t < ray.tmax)) return false;
    hit.t = t;
    hit.point = ray.origin + t * ray.dir;
    hit.normal = glm::normalize(hit.point - s.center);
    hit.point_error = glm::vec3(0.0f);  // no bound stated: secondary rays get a one-ulp offset only
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    const std::size_t rays = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 20000;
    sweeptrace::accuracy::register_routine<collision::Sphere>("textbook", &textbook_sphere);
    const auto rows = sweeptrace::accuracy::run_routines({"sphere"}, rays, 1);
    sweeptrace::accuracy::write_markdown(std::cout, rows);
    sweeptrace::accuracy::write_legend(std::cout);
    return 0;
}
