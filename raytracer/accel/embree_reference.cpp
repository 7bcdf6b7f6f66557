#include "raytracer/accel/embree_reference.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "raytracer/accel/embree_ray.hpp"

namespace sweeptrace {
namespace {

// One device for the process: creating a device costs milliseconds, a scene microseconds.
struct Device {
    RTCDevice device = rtcNewDevice(nullptr);
    ~Device() { rtcReleaseDevice(device); }
};

RTCDevice device() {
    static Device d;
    if (!d.device) throw std::runtime_error("Embree: rtcNewDevice failed");
    return d.device;
}

}  // namespace

EmbreeTriangles::EmbreeTriangles(const std::vector<collision::Triangle>& triangles, bool robust) {
    std::vector<glm::vec3> vertices;
    std::vector<glm::uvec3> indices;
    vertices.reserve(3 * triangles.size());
    indices.reserve(triangles.size());
    for (const auto& t : triangles) {
        const auto i = static_cast<unsigned>(vertices.size());
        vertices.push_back(t.a);
        vertices.push_back(t.b);
        vertices.push_back(t.c);
        indices.push_back({i, i + 1, i + 2});
    }
    build(vertices, indices, robust);
}

EmbreeTriangles::EmbreeTriangles(const collision::TriangleMesh& mesh, bool robust) {
    build(mesh.vertices, mesh.indices, robust);
}

void EmbreeTriangles::build(const std::vector<glm::vec3>& vertices, const std::vector<glm::uvec3>& indices, bool robust) {
    RTCDevice dev = device();
    scene_ = rtcNewScene(dev);
    rtcSetSceneFlags(scene_, robust ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    RTCGeometry geom = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
    // Embree may read 16 bytes from the last vertex: the buffer it allocates is padded for that.
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), vertices.size()));
    auto* ix = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                              3 * sizeof(unsigned), indices.size()));
    if (!v || !ix) throw std::runtime_error("Embree: buffer allocation failed");
    std::memcpy(v, vertices.data(), vertices.size() * 3 * sizeof(float));
    std::memcpy(ix, indices.data(), indices.size() * 3 * sizeof(unsigned));
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene_, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(scene_);
    if (rtcGetDeviceError(dev) != RTC_ERROR_NONE) throw std::runtime_error("Embree: scene build failed");
    // Embree 3 does not report the size of its BVH: this counts the buffers handed to it.
    memory_bytes_ = vertices.size() * 3 * sizeof(float) + indices.size() * 3 * sizeof(unsigned);
}

EmbreeTriangles::~EmbreeTriangles() {
    if (scene_) rtcReleaseScene(scene_);
}

bool EmbreeTriangles::intersect(const collision::Ray& ray, EmbreeTriangleHit& hit) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh = to_embree_ray_hit(ray);
    rtcIntersect1(scene_, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    hit.t = rh.ray.tfar;
    hit.primitive = rh.hit.primID;
    hit.uv = glm::vec2(rh.hit.u, rh.hit.v);
    const glm::vec3 ng(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
    const float len = glm::length(ng);
    hit.normal = len > 0.0f ? ng / len : ng;
    return true;
}

}  // namespace sweeptrace
