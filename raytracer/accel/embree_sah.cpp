#include "raytracer/accel/embree_sah.hpp"

#include <stdexcept>
#include <string>
#include <vector>

#include "raytracer/accel/embree_ray.hpp"
#include "raytracer/accel/sah_cost.hpp"

namespace sweeptrace {
namespace {

// What the callbacks build: enough to score the tree, nothing to trace it.
struct SahNode {
    bool leaf = false;
    unsigned children = 0;
    void* child[8] = {};
    RTCBounds bounds[8] = {};
    std::size_t primitives = 0;
};

void* create_node(RTCThreadLocalAllocator alloc, unsigned children, void*) {
    auto* node = new (rtcThreadLocalAlloc(alloc, sizeof(SahNode), 16)) SahNode;
    node->children = children;
    return node;
}

void set_children(void* node, void** children, unsigned count, void*) {
    for (unsigned i = 0; i < count; ++i) static_cast<SahNode*>(node)->child[i] = children[i];
}

void set_bounds(void* node, const RTCBounds** bounds, unsigned count, void*) {
    for (unsigned i = 0; i < count; ++i) static_cast<SahNode*>(node)->bounds[i] = *bounds[i];
}

void* create_leaf(RTCThreadLocalAllocator alloc, const RTCBuildPrimitive*, size_t count, void*) {
    auto* node = new (rtcThreadLocalAlloc(alloc, sizeof(SahNode), 16)) SahNode;
    node->leaf = true;
    node->primitives = count;
    return node;
}

double area(const RTCBounds& b) {
    return surface_area({b.lower_x, b.lower_y, b.lower_z}, {b.upper_x, b.upper_y, b.upper_z});
}

// Sum of area x weight below `node`, whose own box has area `node_area`.
void score(const SahNode* node, double node_area, EmbreeSah& out) {
    if (node->leaf) {
        out.cost += node_area * static_cast<double>(node->primitives);
        ++out.leaves;
        return;
    }
    out.cost += node_area;
    ++out.inner_nodes;
    for (unsigned i = 0; i < node->children; ++i) score(static_cast<const SahNode*>(node->child[i]), area(node->bounds[i]), out);
}

}  // namespace

EmbreeSah embree_builder_sah(const collision::TriangleMesh& mesh) {
    EmbreeSah out;
    const std::size_t n = mesh.triangle_count();
    if (n == 0) return out;
    std::vector<RTCBuildPrimitive> prims(n);
    RTCBounds root{};
    root.lower_x = root.lower_y = root.lower_z = 1e30f;
    root.upper_x = root.upper_y = root.upper_z = -1e30f;
    for (std::size_t i = 0; i < n; ++i) {
        const collision::Triangle t = mesh.triangle(i);
        const glm::vec3 lo = glm::min(t.a, glm::min(t.b, t.c)), hi = glm::max(t.a, glm::max(t.b, t.c));
        prims[i] = RTCBuildPrimitive{lo.x, lo.y, lo.z, 0u, hi.x, hi.y, hi.z, static_cast<unsigned>(i)};
        root = RTCBounds{std::min(root.lower_x, lo.x), std::min(root.lower_y, lo.y), std::min(root.lower_z, lo.z), 0.0f,
                         std::max(root.upper_x, hi.x), std::max(root.upper_y, hi.y), std::max(root.upper_z, hi.z), 0.0f};
    }
    RTCDevice device = rtcNewDevice("threads=1");
    if (!device) throw std::runtime_error("embree: cannot create a device");
    RTCBVH bvh = rtcNewBVH(device);
    RTCBuildArguments args = rtcDefaultBuildArguments();
    args.byteSize = sizeof(args);
    args.buildQuality = RTC_BUILD_QUALITY_MEDIUM;
    args.maxBranchingFactor = 8;
    args.sahBlockSize = 4;
    args.minLeafSize = 1;
    args.maxLeafSize = 4;
    args.traversalCost = 1.0f;
    args.intersectionCost = 1.0f;
    args.bvh = bvh;
    args.primitives = prims.data();
    args.primitiveCount = n;
    args.primitiveArrayCapacity = n;
    args.createNode = create_node;
    args.setNodeChildren = set_children;
    args.setNodeBounds = set_bounds;
    args.createLeaf = create_leaf;
    const void* top = rtcBuildBVH(&args);
    const RTCError error = rtcGetDeviceError(device);
    if (top && error == RTC_ERROR_NONE) score(static_cast<const SahNode*>(top), area(root), out);
    rtcReleaseBVH(bvh);
    rtcReleaseDevice(device);
    if (!top || error != RTC_ERROR_NONE)
        throw std::runtime_error("embree: rtcBuildBVH failed (error " + std::to_string(static_cast<int>(error)) + ")");
    out.cost /= area(root);
    return out;
}

}  // namespace sweeptrace
