#include "raytracer/accel/sah_cost.hpp"

namespace sweeptrace {

double sah_cost(const collision::Bvh& bvh) {
    if (bvh.nodes.empty()) return 0.0;
    const double root = surface_area(bvh.nodes[0].lo, bvh.nodes[0].hi);
    if (!(root > 0.0)) return 0.0;
    double cost = 0.0;
    for (const collision::BvhNode& n : bvh.nodes) cost += surface_area(n.lo, n.hi) * (n.is_leaf() ? n.count : 1.0);
    return cost / root;
}

}  // namespace sweeptrace
