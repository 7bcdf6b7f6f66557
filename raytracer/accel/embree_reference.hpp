#pragma once
// Embree as the reference for triangle meshes in the accuracy harness: one Embree scene over a
// list of triangles, built with Embree's default flags or with RTC_SCENE_FLAG_ROBUST, and
// single-ray queries. (The renderer's Embree backend is the Accel in embree_accel; this one
// measures Embree's own triangle test, so it keeps no scene objects or transforms.)
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "collision/mesh.hpp"
#include "collision/ray.hpp"
#include "collision/shapes.hpp"

struct RTCSceneTy;

namespace sweeptrace {

struct EmbreeTriangleHit {
    float t = 0.0f;
    std::uint32_t primitive = 0;
    glm::vec2 uv{0.0f};      // Embree's barycentrics of vertices 1 and 2
    glm::vec3 normal{0.0f};  // unit geometric normal, (b - a) x (c - a) as collision/ orients it
};

class EmbreeTriangles {
public:
    EmbreeTriangles(const std::vector<collision::Triangle>& triangles, bool robust);
    EmbreeTriangles(const collision::TriangleMesh& mesh, bool robust);
    ~EmbreeTriangles();
    EmbreeTriangles(const EmbreeTriangles&) = delete;
    EmbreeTriangles& operator=(const EmbreeTriangles&) = delete;

    // Nearest hit with ray.tmin <= t <= ray.tmax (Embree's inclusive interval).
    bool intersect(const collision::Ray& ray, EmbreeTriangleHit& hit) const;
    // Bytes of the vertex and index buffers (Embree 3 does not report its BVH's size).
    std::size_t memory_bytes() const { return memory_bytes_; }

private:
    void build(const std::vector<glm::vec3>& vertices, const std::vector<glm::uvec3>& indices, bool robust);
    RTCSceneTy* scene_ = nullptr;
    std::size_t memory_bytes_ = 0;
};

}  // namespace sweeptrace
