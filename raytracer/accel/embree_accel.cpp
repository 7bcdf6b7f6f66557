#include "raytracer/accel/embree_accel.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>


#include "collision/triangle_watertight.hpp"
#include "raytracer/accel/embree_ray.hpp"
#include "raytracer/geometry/object_space.hpp"
#include "raytracer/geometry/shape.hpp"
#include "raytracer/geometry/intersect_object.hpp"

namespace sweeptrace {
namespace {

// Embree's intersect context extended with where the user-geometry callbacks leave the full
// SurfaceHit of the nearest analytic hit so far (the usual Embree idiom: the context pointer
// the callbacks receive is this struct's first member).
struct HitContext {
    RTCIntersectContext embree;
    SurfaceHit* hit;
};

struct UserObject {
    const Scene* scene;
    std::uint32_t object;
    std::vector<collision::Bounds3> step_bounds;  // a moving object's box per Embree time step
};

class EmbreeAccel final : public Accel {
public:
    EmbreeAccel(const Scene& scene, const EmbreeOptions& options);
    ~EmbreeAccel() override;
    EmbreeAccel(const EmbreeAccel&) = delete;
    EmbreeAccel& operator=(const EmbreeAccel&) = delete;

    bool intersect(const collision::Ray& ray, SurfaceHit& hit) const override;
    bool occluded(const collision::Ray& ray) const override;
    bool intersect(const collision::Ray& ray, float time, SurfaceHit& hit) const override;
    bool occluded(const collision::Ray& ray, float time) const override;
    std::size_t memory_bytes() const override;
    std::string name() const override { return robust_ ? "embree-robust" : "embree"; }

private:
    void build(const EmbreeOptions& options);
    void release();
    void check(const char* what) const;
    void set_instance_motion(RTCGeometry instance, const Motion& motion) const;

    const Scene& scene_;
    bool robust_;
    RTCDevice device_ = nullptr;
    RTCScene top_ = nullptr;
    std::vector<RTCScene> mesh_scenes_;   // per Scene::meshes entry, null if unused
    std::vector<std::uint32_t> object_of_geometry_;  // top-level geometry ID -> object
    std::vector<UserObject> user_objects_;           // stable storage for callback user data
    std::atomic<std::int64_t> embree_bytes_{0};
};

bool track_memory(void* user, ssize_t bytes, bool /*post*/) {
    static_cast<std::atomic<std::int64_t>*>(user)->fetch_add(bytes, std::memory_order_relaxed);
    return true;
}

collision::Ray to_ray(const RTCRay& r) {
    return collision::Ray{{r.org_x, r.org_y, r.org_z}, {r.dir_x, r.dir_y, r.dir_z}, r.tnear, r.tfar};
}

// A moving object has Embree time steps; its box at each (motion_step_bounds) interpolates
// linearly to hold it between them, which is how Embree's motion blur BVH reads them.
void user_bounds(const RTCBoundsFunctionArguments* args) {
    const auto* user = static_cast<const UserObject*>(args->geometryUserPtr);
    const Object& object = user->scene->objects[user->object];
    const collision::Bounds3 b = !user->step_bounds.empty() ? user->step_bounds[args->timeStep]
                                                            : world_bounds(object.transform, object_space_bounds(object.shape));
    *args->bounds_o = RTCBounds{b.lo.x, b.lo.y, b.lo.z, 0.0f, b.hi.x, b.hi.y, b.hi.z, 0.0f};
}

void user_intersect(const RTCIntersectFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;  // only rtcIntersect1 is used
    const auto* user = static_cast<const UserObject*>(args->geometryUserPtr);
    auto* rayhit = reinterpret_cast<RTCRayHit*>(args->rayhit);
    SurfaceHit hit;
    if (!intersect_object_at(user->scene->objects, user->scene->meshes, user->object, to_ray(rayhit->ray),
                             rayhit->ray.time, hit))
        return;
    rayhit->ray.tfar = hit.t;
    rayhit->hit.geomID = args->geomID;
    rayhit->hit.primID = args->primID;
    rayhit->hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rayhit->hit.Ng_x = hit.normal.x;
    rayhit->hit.Ng_y = hit.normal.y;
    rayhit->hit.Ng_z = hit.normal.z;
    rayhit->hit.u = hit.uv.x;
    rayhit->hit.v = hit.uv.y;
    *reinterpret_cast<HitContext*>(args->context)->hit = hit;
}

void user_occluded(const RTCOccludedFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;
    const auto* user = static_cast<const UserObject*>(args->geometryUserPtr);
    auto* ray = reinterpret_cast<RTCRay*>(args->ray);
    SurfaceHit hit;
    if (intersect_object_at(user->scene->objects, user->scene->meshes, user->object, to_ray(*ray), ray->time, hit))
        ray->tfar = -std::numeric_limits<float>::infinity();  // Embree's "occluded" mark
}

EmbreeAccel::EmbreeAccel(const Scene& scene, const EmbreeOptions& options)
    : scene_(scene), robust_(options.robust), mesh_scenes_(scene.meshes.size(), nullptr) {
    try {
        build(options);
    } catch (...) {
        release();  // the destructor does not run for a constructor that throws
        throw;
    }
}

void EmbreeAccel::build(const EmbreeOptions& options) {
    const std::string config = options.build_threads > 0 ? "threads=" + std::to_string(options.build_threads) : "";
    device_ = rtcNewDevice(config.c_str());
    if (!device_) throw std::runtime_error("embree: cannot create a device");
    rtcSetDeviceMemoryMonitorFunction(device_, track_memory, &embree_bytes_);
    const Scene& scene = scene_;
    const RTCSceneFlags flags = robust_ ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE;
    top_ = rtcNewScene(device_);
    rtcSetSceneFlags(top_, flags);

    user_objects_.reserve(scene.objects.size());
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        const Object& object = scene.objects[i];
        RTCGeometry geometry;
        if (const auto* instance = std::get_if<MeshInstance>(&object.shape)) {
            const Mesh& mesh = scene.meshes[instance->mesh];
            if (mesh.triangles.triangle_count() == 0) continue;
            RTCScene& mesh_scene = mesh_scenes_[instance->mesh];
            if (!mesh_scene) {
                mesh_scene = rtcNewScene(device_);
                rtcSetSceneFlags(mesh_scene, flags);
                RTCGeometry tri = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
                // Embree-allocated buffers: they carry the padding its SIMD loads need, which
                // the scene's own vectors do not guarantee.
                auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(tri, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                      3 * sizeof(float), mesh.triangles.vertices.size()));
                for (const glm::vec3& p : mesh.triangles.vertices) {
                    *v++ = p.x;
                    *v++ = p.y;
                    *v++ = p.z;
                }
                auto* ix = static_cast<unsigned*>(rtcSetNewGeometryBuffer(tri, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                          3 * sizeof(unsigned), mesh.triangles.indices.size()));
                for (const glm::uvec3& f : mesh.triangles.indices) {
                    *ix++ = f.x;
                    *ix++ = f.y;
                    *ix++ = f.z;
                }
                rtcCommitGeometry(tri);
                rtcAttachGeometry(mesh_scene, tri);
                rtcReleaseGeometry(tri);
                rtcCommitScene(mesh_scene);
            }
            geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
            rtcSetGeometryInstancedScene(geometry, mesh_scene);
            if (object.motion.moving()) set_instance_motion(geometry, object.motion);
            else rtcSetGeometryTransform(geometry, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, &object.transform.to_world[0][0]);
        } else {
            user_objects_.push_back(UserObject{&scene, i, {}});
            geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
            if (object.motion.moving()) {
                const int steps = motion_time_steps(object.motion);
                user_objects_.back().step_bounds = motion_step_bounds(object.motion, object_space_bounds(object.shape), steps);
                rtcSetGeometryTimeStepCount(geometry, static_cast<unsigned>(steps));
            }
            rtcSetGeometryUserPrimitiveCount(geometry, 1);
            rtcSetGeometryUserData(geometry, &user_objects_.back());
            rtcSetGeometryBoundsFunction(geometry, user_bounds, nullptr);
            rtcSetGeometryIntersectFunction(geometry, user_intersect);
            rtcSetGeometryOccludedFunction(geometry, user_occluded);
        }
        rtcCommitGeometry(geometry);
        const unsigned id = rtcAttachGeometry(top_, geometry);
        rtcReleaseGeometry(geometry);
        if (object_of_geometry_.size() <= id) object_of_geometry_.resize(id + 1);
        object_of_geometry_[id] = i;
    }
    rtcCommitScene(top_);
    check("building the scene");
}

// A moving mesh instance: one Embree time step per key. Translation only: the key matrices, which
// Embree interpolates linearly, as pose_at does. With rotation: Embree's quaternion decomposition
// (M = T R U, U upper triangular: scale, skew, shift), which it interpolates as pose_at does (T
// and U linear, R by slerp) when every key's stretch S is diagonal, U = S; the rotation's sign
// is the one make_motion aligned along the shorter arc. A stretch with off-diagonal terms (a
// shear, or a non-uniform scale applied after a rotation) has no such U: the keys are then
// given as matrices, and between keys Embree's pose departs from the native one.
void EmbreeAccel::set_instance_motion(RTCGeometry instance, const Motion& motion) const {
    const auto steps = static_cast<unsigned>(motion.keys.size());
    rtcSetGeometryTimeStepCount(instance, steps);
    // Diagonal up to the float rounding of the key matrices (a float rotation times a scale has
    // a polar stretch with off-diagonal terms of a few 1e-8 of its diagonal).
    bool diagonal = true;
    for (const PoseParts& p : motion.parts) {
        const double scale = std::max({std::abs(p.stretch[0][0]), std::abs(p.stretch[1][1]), std::abs(p.stretch[2][2])});
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r)
                if (r != c && std::abs(p.stretch[c][r]) > 1e-6 * scale) diagonal = false;
    }
    for (unsigned k = 0; k < steps; ++k) {
        if (motion.translation_only || !diagonal) {
            rtcSetGeometryTransform(instance, k, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, &motion.keys[k].to_world[0][0]);
            continue;
        }
        const PoseParts& p = motion.parts[k];
        RTCQuaternionDecomposition q;
        rtcInitQuaternionDecomposition(&q);
        rtcQuaternionDecompositionSetScale(&q, static_cast<float>(p.stretch[0][0]), static_cast<float>(p.stretch[1][1]),
                                           static_cast<float>(p.stretch[2][2]));
        rtcQuaternionDecompositionSetQuaternion(&q, static_cast<float>(p.rotation[0]), static_cast<float>(p.rotation[1]),
                                                static_cast<float>(p.rotation[2]), static_cast<float>(p.rotation[3]));
        rtcQuaternionDecompositionSetTranslation(&q, static_cast<float>(p.translation.x), static_cast<float>(p.translation.y),
                                                 static_cast<float>(p.translation.z));
        rtcSetGeometryTransformQuaternion(instance, k, &q);
    }
}

EmbreeAccel::~EmbreeAccel() { release(); }

void EmbreeAccel::release() {
    if (top_) rtcReleaseScene(top_);
    top_ = nullptr;
    for (RTCScene& s : mesh_scenes_) {
        if (s) rtcReleaseScene(s);
        s = nullptr;
    }
    if (device_) rtcReleaseDevice(device_);
    device_ = nullptr;
}

void EmbreeAccel::check(const char* what) const {
    const RTCError error = rtcGetDeviceError(device_);
    if (error != RTC_ERROR_NONE)
        throw std::runtime_error(std::string("embree: error ") + std::to_string(static_cast<int>(error)) + " while " +
                                 what);
}

bool EmbreeAccel::intersect(const collision::Ray& ray, SurfaceHit& hit) const { return intersect(ray, 0.0f, hit); }

bool EmbreeAccel::intersect(const collision::Ray& ray, float time, SurfaceHit& hit) const {
    SurfaceHit analytic;
    HitContext context{{}, &analytic};
    rtcInitIntersectContext(&context.embree);
    RTCRayHit rh = to_embree_ray_hit(ray);
    rh.ray.time = time;
    rtcIntersect1(top_, &context.embree, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    if (rh.hit.instID[0] == RTC_INVALID_GEOMETRY_ID) {  // an analytic object: its callback's hit
        hit = analytic;
        return true;
    }
    // A mesh triangle: rebuild the hit from Embree's t and barycentrics exactly as the native
    // path does (same point, error bound, normals), in the instancing object's space.
    const std::uint32_t object_index = object_of_geometry_[rh.hit.instID[0]];
    const Object& object = scene_.objects[object_index];
    const Mesh& mesh = scene_.meshes[std::get<MeshInstance>(object.shape).mesh];
    const collision::Triangle tri = mesh.triangles.triangle(rh.hit.primID);
    collision::TriangleCandidate candidate;
    candidate.t = rh.ray.tfar;
    candidate.b1 = rh.hit.u;
    candidate.b2 = rh.hit.v;
    candidate.b0 = 1.0f - rh.hit.u - rh.hit.v;
    collision::RayHit h;
    collision::finish_triangle_hit(tri.a, tri.b, tri.c, candidate, h);
    mesh_hit_to_world(mesh, object_transform_at(object, time), object_index, rh.hit.primID, h, 0.0f, hit);
    return true;
}

bool EmbreeAccel::occluded(const collision::Ray& ray) const { return occluded(ray, 0.0f); }

bool EmbreeAccel::occluded(const collision::Ray& ray, float time) const {
    HitContext context{{}, nullptr};
    rtcInitIntersectContext(&context.embree);
    RTCRay r = to_embree_ray(ray);
    r.time = time;
    rtcOccluded1(top_, &context.embree, &r);
    return r.tfar == -std::numeric_limits<float>::infinity();
}

std::size_t EmbreeAccel::memory_bytes() const {
    const std::int64_t embree = embree_bytes_.load(std::memory_order_relaxed);
    return sizeof(*this) + static_cast<std::size_t>(embree > 0 ? embree : 0) +
           mesh_scenes_.capacity() * sizeof(RTCScene) + object_of_geometry_.capacity() * sizeof(std::uint32_t) +
           user_objects_.capacity() * sizeof(UserObject);
}

}  // namespace

std::unique_ptr<Accel> make_embree_accel(const Scene& scene, const EmbreeOptions& options) {
    return std::make_unique<EmbreeAccel>(scene, options);
}

}  // namespace sweeptrace
