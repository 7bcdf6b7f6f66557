// The hashed uniform grid (thesis 3.4) and its 3.5.3 defect, fixed.
#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>
#include <set>
#include <stdexcept>

#include "collision/hashed_grid.hpp"
#include "random_cases.hpp"

using namespace collision;

namespace {
// The worst hash there is: every cell collides with every other.
struct ConstantHash {
    std::size_t operator()(const glm::ivec3&) const noexcept { return 42; }
};

// Brute-force answer: ids whose box shares a cell with the query box.
template <class Grid>
std::vector<std::uint32_t> brute(const std::vector<Aabb>& boxes, const Aabb& q, const Grid& g) {
    const CellRange qr = cell_range(q.min(), q.max(), g.cell_size());
    std::vector<std::uint32_t> out;
    for (std::uint32_t i = 0; i < boxes.size(); ++i) {
        const CellRange r = cell_range(boxes[i].min(), boxes[i].max(), g.cell_size());
        bool share = true;
        for (int k = 0; k < 3; ++k) share = share && r.lo[k] <= qr.hi[k] && qr.lo[k] <= r.hi[k];
        if (share) out.push_back(i);
    }
    return out;
}
}  // namespace

TEST_CASE("hashed grid: cells of points and boxes, closed boundaries, negative coordinates", "[grid]") {
    HashedGrid<> g(2.0f);
    CHECK(g.cell_of({0, 0, 0}) == glm::ivec3(0, 0, 0));
    CHECK(g.cell_of({1.999f, 2.0f, -0.001f}) == glm::ivec3(0, 1, -1));
    CHECK(g.cell_of({-4, -4.5f, 7}) == glm::ivec3(-2, -3, 3));
    const CellRange r = cell_range({-1, 0, 0}, {2, 0.5f, 3.9f}, 2.0);
    REQUIRE(r.valid);
    CHECK(r.lo == glm::ivec3(-1, 0, 0));
    CHECK(r.hi == glm::ivec3(1, 0, 1));  // hi.x = 2 lies on the face of cell 1: closed box
    CHECK(r.count() == 6);
}

TEST_CASE("hashed grid: insert and query by box, ids once, neighbourhood query", "[grid]") {
    HashedGrid<> g(1.0f);
    REQUIRE(g.insert(7, Aabb{{0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}}));  // one cell
    REQUIRE(g.insert(8, Aabb{{1.0f, 0.5f, 0.5f}, {1.5f, 0.5f, 0.5f}}));  // cells x = 0 and 1
    REQUIRE(g.insert(9, Aabb{{5.5f, 5.5f, 5.5f}, {0.2f, 0.2f, 0.2f}}));
    CHECK(g.occupied_cells() == 3);
    CHECK(g.query(Aabb{{0.5f, 0.5f, 0.5f}, {0.1f, 0.1f, 0.1f}}) == std::vector<std::uint32_t>{7, 8});
    CHECK(g.query(Aabb{{1.5f, 0.5f, 0.5f}, {0.1f, 0.1f, 0.1f}}) == std::vector<std::uint32_t>{8});
    CHECK(g.query(Aabb{{1.0f, 0.5f, 0.5f}, {3, 3, 3}}) == std::vector<std::uint32_t>{7, 8});  // 8 once
    CHECK(g.query(Aabb{{3.5f, 3.5f, 3.5f}, {0.1f, 0.1f, 0.1f}}).empty());
    CHECK(g.query_around({2.5f, 0.5f, 0.5f}) == std::vector<std::uint32_t>{8});
    CHECK(g.query_around({4.5f, 4.5f, 4.5f}) == std::vector<std::uint32_t>{9});
    CHECK(g.cell({1, 0, 0}).size() == 1);
    CHECK(g.cell({3, 3, 3}).empty());
    g.clear();
    CHECK(g.occupied_cells() == 0);
}

TEST_CASE("hashed grid: bad input is rejected, not stored", "[grid]") {
    const float qnan = std::numeric_limits<float>::quiet_NaN();
    const float qinf = std::numeric_limits<float>::infinity();
    CHECK_THROWS_AS(HashedGrid<>(0.0f), std::invalid_argument);
    CHECK_THROWS_AS(HashedGrid<>(-1.0f), std::invalid_argument);
    CHECK_THROWS_AS(HashedGrid<>(qnan), std::invalid_argument);
    HashedGrid<> g(1.0f);
    CHECK_FALSE(g.insert(1, glm::vec3(0, qnan, 0), glm::vec3(1, 1, 1)));
    CHECK_FALSE(g.insert(1, glm::vec3(0, 0, 0), glm::vec3(qinf, 1, 1)));
    CHECK_FALSE(g.insert(1, glm::vec3(1, 0, 0), glm::vec3(0, 1, 1)));        // inverted
    CHECK_FALSE(g.insert(1, glm::vec3(-1e30f), glm::vec3(1e30f)));            // beyond int cells
    CHECK_FALSE(g.insert(1, glm::vec3(0), glm::vec3(1000, 1000, 1000)));      // > 2^24 cells
    CHECK(g.occupied_cells() == 0);
    CHECK(g.query(glm::vec3(0, qnan, 0), glm::vec3(1)).empty());
    // Cells at the very edge of int range work, without overflow in the loops.
    HashedGrid<> edge(1.0f);
    const float top = 2147483520.0f;  // largest float below 2^31
    REQUIRE(edge.insert(3, glm::vec3(top), glm::vec3(top)));
    CHECK(edge.query(glm::vec3(top), glm::vec3(top)) == std::vector<std::uint32_t>{3});
}

TEST_CASE("hashed grid: every cell colliding in the hash returns no foreign ids (thesis 3.5.3)", "[grid][hash]") {
    // With a constant hash all cells share one bucket chain. The thesis's table compared only
    // hashes, so any query returned every object; here keys are compared in full.
    HashedGrid<ConstantHash> bad(1.0f);
    HashedGrid<> good(1.0f);
    testing::SeededRng rng(3);
    std::vector<Aabb> boxes;
    for (std::uint32_t i = 0; i < 300; ++i) {
        const Aabb b{rng.vec(-20, 20), rng.vec(0.1f, 2.0f)};
        boxes.push_back(b);
        REQUIRE(bad.insert(i, b));
        REQUIRE(good.insert(i, b));
    }
    CHECK(bad.occupied_cells() == good.occupied_cells());
    int nonempty = 0;
    for (int k = 0; k < 300; ++k) {
        const Aabb q{rng.vec(-20, 20), rng.vec(0.1f, 3.0f)};
        const auto got = bad.query(q);
        CHECK(got == good.query(q));
        CHECK(got == brute(boxes, q, bad));
        CHECK(got.size() < boxes.size() / 4);  // nowhere near "everything"
        nonempty += !got.empty();
    }
    CHECK(nonempty > 30);
    // A cell nobody touched is empty even though its hash equals every occupied cell's.
    CHECK(bad.cell({1000, 1000, 1000}).empty());
}
