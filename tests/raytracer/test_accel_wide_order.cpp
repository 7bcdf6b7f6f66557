// The collapse's child order (wide_bvh.hpp): each wide node's children sorted by box centre along
// the axis recorded for the node (WideBvh::axis), the axis where those centres spread most. The
// any-hit traversal reads that order as the order of the children along the ray, so a node out
// of order would only cost speed; this checks the invariant the traversal's comment relies on.
#include <catch2/catch.hpp>

#include <limits>
#include <random>
#include <vector>

#include "raytracer/accel/wide_bvh.hpp"

using namespace sweeptrace;

TEST_CASE("wide bvh: each node's children are in the order of their centres along its axis", "[accel][wide]") {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-10.0f, 10.0f), size(0.0f, 0.5f), stretch(0.2f, 5.0f);
    for (int n : {9, 100, 3000}) {
        // Stretched along a random-ish axis scale, so nodes' widest spreads differ.
        const glm::vec3 scale(stretch(rng), stretch(rng), stretch(rng));
        std::vector<collision::Bounds3> boxes(static_cast<std::size_t>(n));
        std::vector<glm::vec3> centroids;
        for (auto& b : boxes) {
            const glm::vec3 c = scale * glm::vec3(u(rng), u(rng), u(rng));
            b = collision::Bounds3{c - size(rng), c + size(rng)};
            centroids.push_back(0.5f * (b.lo + b.hi));
        }
        collision::BvhBuildOptions options;
        options.max_leaf_size = 4;
        const WideBvh tree = collapse_to_wide(collision::build_bvh(boxes, centroids, options), 8);
        REQUIRE(tree.axis.size() == tree.nodes.size());
        for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
            const WideNode& node = tree.nodes[i];
            const int axis = tree.axis[i];
            REQUIRE(axis < 3);
            glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
            float previous = -std::numeric_limits<float>::infinity();
            bool empty_seen = false;
            for (int slot = 0; slot < kWideWidth; ++slot) {
                if (node.child[slot] == wide_ref::empty) {
                    empty_seen = true;
                    continue;
                }
                REQUIRE_FALSE(empty_seen);  // used slots first
                glm::vec3 centre;
                for (int a = 0; a < 3; ++a) centre[a] = 0.5f * (node.box[a][0][slot] + node.box[a][1][slot]);
                REQUIRE(centre[axis] >= previous);
                previous = centre[axis];
                lo = glm::min(lo, centre);
                hi = glm::max(hi, centre);
            }
            const glm::vec3 spread = hi - lo;
            for (int a = 0; a < 3; ++a) REQUIRE(spread[axis] >= spread[a]);
        }
    }
}
