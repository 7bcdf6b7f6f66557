#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include <glm/vector_relational.hpp>

#include "collision/bvh.hpp"

using collision::Bounds3;
using collision::Bvh;
using collision::BvhNode;

namespace {

struct Prims {
    std::vector<Bounds3> boxes;
    std::vector<glm::vec3> centroids;
    void add(const glm::vec3& lo, const glm::vec3& hi) {
        boxes.push_back(Bounds3{lo, hi});
        centroids.push_back(0.5f * (lo + hi));
    }
};

Prims random_prims(std::size_t n, std::uint32_t seed, float world = 100.0f, float size = 2.0f) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> pos(-world, world), ext(0.0f, size);
    Prims p;
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3 lo(pos(rng), pos(rng), pos(rng));
        p.add(lo, lo + glm::vec3(ext(rng), ext(rng), ext(rng)));
    }
    return p;
}

bool contains(const glm::vec3& lo, const glm::vec3& hi, const Bounds3& b) {
    return glm::all(glm::lessThanEqual(lo, b.lo)) && glm::all(glm::lessThanEqual(b.hi, hi));
}

// Walks the whole tree and checks the invariants every user relies on: each primitive is in
// exactly one leaf, each box holds everything below it, leaves are no larger than asked, and
// the depth is what the tree reports. Returns the number of leaves.
std::size_t check_tree(const Bvh& bvh, const Prims& p, int max_leaf) {
    const std::size_t n = p.boxes.size();
    REQUIRE(bvh.prim_indices.size() == n);
    std::vector<int> seen(n, 0);
    std::size_t leaves = 0;
    int deepest = 0;
    struct Item {
        std::uint32_t node;
        int depth;
    };
    std::vector<Item> stack{{0, 0}};
    while (!stack.empty()) {
        const Item it = stack.back();
        stack.pop_back();
        REQUIRE(it.node < bvh.nodes.size());
        const BvhNode& node = bvh.nodes[it.node];
        deepest = std::max(deepest, it.depth);
        if (node.is_leaf()) {
            ++leaves;
            REQUIRE(node.count <= static_cast<std::uint32_t>(max_leaf));
            REQUIRE(node.first + node.count <= n);
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                const std::uint32_t prim = bvh.prim_indices[i];
                REQUIRE(prim < n);
                ++seen[prim];
                REQUIRE(contains(node.lo, node.hi, p.boxes[prim]));
            }
        } else {
            REQUIRE(node.first + 1 < bvh.nodes.size());
            for (std::uint32_t c = node.first; c <= node.first + 1; ++c) {
                REQUIRE(contains(node.lo, node.hi, Bounds3{bvh.nodes[c].lo, bvh.nodes[c].hi}));
                stack.push_back({c, it.depth + 1});
            }
        }
    }
    CHECK(std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; }));
    CHECK(deepest == bvh.depth);
    CHECK(bvh.depth <= Bvh::max_depth);
    CHECK(bvh.nodes.size() == 2 * leaves - 1);
    return leaves;
}

bool overlaps(const Bounds3& a, const glm::vec3& lo, const glm::vec3& hi) {
    return glm::all(glm::lessThanEqual(a.lo, hi)) && glm::all(glm::lessThanEqual(lo, a.hi));
}

}  // namespace

TEST_CASE("bvh: random boxes give a valid tree holding every primitive once", "[bvh]") {
    for (std::size_t n : {1u, 2u, 3u, 17u, 1000u, 20000u}) {
        const Prims p = random_prims(n, static_cast<std::uint32_t>(n));
        const Bvh bvh = collision::build_bvh(p.boxes, p.centroids);
        check_tree(bvh, p, collision::BvhBuildOptions{}.max_leaf_size);
        // The root box is exactly the union of all input boxes (min/max are exact).
        Bounds3 all;
        for (const Bounds3& b : p.boxes) all.extend(b);
        CHECK(bvh.nodes[0].lo == all.lo);
        CHECK(bvh.nodes[0].hi == all.hi);
    }
}

TEST_CASE("bvh: a box query through the tree finds exactly what brute force finds", "[bvh]") {
    const Prims p = random_prims(5000, 7);
    const Bvh bvh = collision::build_bvh(p.boxes, p.centroids);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> pos(-110.0f, 110.0f), ext(0.0f, 30.0f);
    for (int q = 0; q < 200; ++q) {
        const glm::vec3 lo(pos(rng), pos(rng), pos(rng));
        const glm::vec3 hi = lo + glm::vec3(ext(rng), ext(rng), ext(rng));
        std::vector<std::uint32_t> brute, tree;
        for (std::uint32_t i = 0; i < p.boxes.size(); ++i)
            if (overlaps(p.boxes[i], lo, hi)) brute.push_back(i);
        std::vector<std::uint32_t> stack{0};
        while (!stack.empty()) {
            const BvhNode& node = bvh.nodes[stack.back()];
            stack.pop_back();
            if (!overlaps(Bounds3{node.lo, node.hi}, lo, hi)) continue;
            if (node.is_leaf()) {
                for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
                    if (overlaps(p.boxes[bvh.prim_indices[i]], lo, hi)) tree.push_back(bvh.prim_indices[i]);
            } else {
                stack.push_back(node.first);
                stack.push_back(node.first + 1);
            }
        }
        std::sort(tree.begin(), tree.end());
        REQUIRE(tree == brute);
    }
}

TEST_CASE("bvh: the SAH separates two distant clusters at the root", "[bvh]") {
    Prims p = random_prims(300, 3, 1.0f, 0.1f);
    const Prims far = random_prims(300, 4, 1.0f, 0.1f);
    for (const Bounds3& b : far.boxes) p.add(b.lo + glm::vec3(0.0f, 1000.0f, 0.0f), b.hi + glm::vec3(0.0f, 1000.0f, 0.0f));
    const Bvh bvh = collision::build_bvh(p.boxes, p.centroids);
    check_tree(bvh, p, collision::BvhBuildOptions{}.max_leaf_size);
    const BvhNode& root = bvh.nodes[0];
    REQUIRE_FALSE(root.is_leaf());
    const BvhNode& a = bvh.nodes[root.first];
    const BvhNode& b = bvh.nodes[root.first + 1];
    // One child holds exactly the low cluster (y <= 2), the other the high one.
    CHECK(std::min(a.hi.y, b.hi.y) < 2.0f);
    CHECK(std::max(a.lo.y, b.lo.y) > 900.0f);
}

TEST_CASE("bvh: coincident centroids and skewed spacing still give bounded depth and small leaves", "[bvh]") {
    SECTION("all primitives at one point: median splits") {
        Prims p;
        for (int i = 0; i < 1000; ++i) p.add(glm::vec3(-1.0f), glm::vec3(1.0f));
        const Bvh bvh = collision::build_bvh(p.boxes, p.centroids);
        check_tree(bvh, p, collision::BvhBuildOptions{}.max_leaf_size);
        CHECK(bvh.depth <= 10);  // ceil(log2(1000 / 8)) + 1 levels of halving
    }
    SECTION("exponentially spaced primitives: binning peels one off per level until the depth limit") {
        Prims p;
        for (int i = 0; i < 3000; ++i) {
            const float x = std::ldexp(1.0f, i / 25);  // 1 .. 2^119: each bin step swallows all below
            p.add(glm::vec3(x, 0.0f, 0.0f), glm::vec3(x * 1.001f, 1.0f, 1.0f));
        }
        const Bvh bvh = collision::build_bvh(p.boxes, p.centroids);
        check_tree(bvh, p, collision::BvhBuildOptions{}.max_leaf_size);
    }
    SECTION("max_leaf_size 1 makes one primitive per leaf") {
        const Prims p = random_prims(500, 9);
        collision::BvhBuildOptions opt;
        opt.max_leaf_size = 1;
        const Bvh bvh = collision::build_bvh(p.boxes, p.centroids, opt);
        CHECK(check_tree(bvh, p, 1) == 500);
    }
}

TEST_CASE("bvh: empty input, mismatched lengths and non-finite input", "[bvh]") {
    const Bvh empty = collision::build_bvh({}, {});
    CHECK(empty.nodes.empty());
    CHECK(empty.prim_indices.empty());
    Prims p = random_prims(4, 1);
    std::vector<glm::vec3> short_centroids(p.centroids.begin(), p.centroids.end() - 1);
    CHECK_THROWS_AS(collision::build_bvh(p.boxes, short_centroids), std::invalid_argument);
    p.boxes[2].hi.y = std::numeric_limits<float>::quiet_NaN();
    CHECK_THROWS_AS(collision::build_bvh(p.boxes, p.centroids), std::invalid_argument);
}

TEST_CASE("bvh: the same input builds the same tree", "[bvh]") {
    const Prims p = random_prims(3000, 5);
    const Bvh a = collision::build_bvh(p.boxes, p.centroids);
    const Bvh b = collision::build_bvh(p.boxes, p.centroids);
    REQUIRE(a.nodes.size() == b.nodes.size());
    CHECK(a.prim_indices == b.prim_indices);
    for (std::size_t i = 0; i < a.nodes.size(); ++i) {
        CHECK(a.nodes[i].first == b.nodes[i].first);
        CHECK(a.nodes[i].count == b.nodes[i].count);
    }
}
