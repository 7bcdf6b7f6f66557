#pragma once
// The directional half of path guiding (Müller, Gross, Novák 2017, "Practical Path Guiding",
// §3.3): a distribution of incident radiance over the unit sphere, as a quadtree over the square
// [0, 1)^2 that the cylindrical map takes to the sphere,
//     (u, v) = ((cos theta + 1) / 2, phi / 2 pi),   theta, phi of the direction about world +z,
// which preserves area (dA_sphere = 4 pi du dv), so a density on the square divided by 4 pi is
// the density on the sphere. Each node holds the recorded energy of its four quadrants; a
// quadrant is either a leaf or another node. Sampling descends choosing quadrants in proportion
// to their energy and ends uniform inside a leaf; pdf() follows the same descent, so the density
// it returns is the one sample() draws with (both read the same per-node probabilities, which
// freeze() computes once in float: equal up to float rounding).
//
// Quadrant order: index = x_bit + 2 y_bit, x_bit = (u >= mid), y_bit = (v >= mid).
// A tree with zero energy has no distribution: callers check total() > 0 before sample/pdf.
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace sweeptrace {

// The equal-area cylindrical map and its inverse (unit direction <-> point of [0, 1)^2).
glm::vec2 direction_to_square(const glm::vec3& dir);
glm::vec3 square_to_direction(const glm::vec2& p);

class DirectionalQuadtree {
public:
    DirectionalQuadtree();  // a root of four empty leaves

    // Adds `value` (>= 0) to the leaf holding direction `dir` and to every quadrant above it.
    void record(const glm::vec3& dir, float value);
    // The same on the square itself (the tree is a distribution over [0, 1)^2; the guide for
    // next event estimation uses it on a light's sample square, with no map to the sphere).
    void record_square(const glm::vec2& p, float value);
    double total() const;

    // Computes the ratios sample() and pdf() read from the energies; call once recording is done.
    void freeze();
    // A direction drawn from the tree's distribution, from two uniforms in [0, 1).
    // Requires total() > 0 and freeze(). With `density`, also its solid-angle density, the
    // product of the descent's factors: what pdf() of the direction gives (the same factors of
    // the same cells), without mapping it back (an atan2 and a second descent).
    glm::vec3 sample(float u1, float u2, float* density = nullptr) const;
    // Solid-angle density of sample() producing `dir`. Requires total() > 0 and freeze().
    float pdf(const glm::vec3& dir) const;
    // The same two on the square: a point of [0, 1)^2 and its density there (area 1).
    glm::vec2 sample_square(float u1, float u2, float* density = nullptr) const;
    float pdf_square(const glm::vec2& p) const;

    // The structure for the next training iteration (PPG §3.4): a quadrant is a node when its
    // share of this tree's energy exceeds `threshold` and it is shallower than `max_depth`
    // (a leaf's energy counts as spread evenly over its would-be children); all energy zero.
    DirectionalQuadtree refined(double threshold, int max_depth) const;

    // Starts loading the top of the tree (its first levels: refined() lays it out breadth
    // first) into the cache, for a path vertex to call as soon as it knows its spatial leaf: the
    // descents come after the light sample and its shadow ray.
    void prefetch() const;

    std::size_t node_count() const { return nodes_.size(); }
    int depth() const;

private:
    // Hot and cold halves apart, and the hot half small: a guided vertex lands in a random
    // spatial leaf, so its descent's loads miss the cache (measured: 70% of sample()'s time was
    // the load of the next node). 16 bytes a node, four to a cache line (32 bytes made sample()
    // and pdf() 10% of a guided smallpt render; 64, with reciprocals to save the divisions, 20%).
    // freeze() stores the descent's choices as probabilities in units of 1/65535: the lower
    // column's, and each column's lower quadrant's. sample() and pdf() read the same numbers, so
    // they agree by construction; a share that rounds to 0 is never sampled, and has density 0.
    struct Node {
        std::uint16_t child[4] = {0, 0, 0, 0};  // 0: the quadrant is a leaf (node 0 is the root)
        std::uint16_t low_x = kHalf;            // P(x_bit = 0)
        std::uint16_t low_y[2] = {kHalf, kHalf};  // P(y_bit = 0 | x_bit)
        std::uint16_t pad = 0;
    };
    static constexpr std::uint16_t kHalf = 32768;
    static constexpr float kUnit = 1.0f / 65535.0f;
    static constexpr std::size_t kMaxNodes = 65535;  // child indices are 16-bit
    static constexpr std::size_t kPrefetchBytes = 256;  // prefetch(): the first 16 nodes
    // 4 P(quadrant): the density factor of one level (the quadrant is a quarter of the cell).
    static float factor(const Node& n, int xb, int yb) {
        const float px = float(xb ? 65535 - n.low_x : n.low_x) * kUnit;
        const float py = float(yb ? 65535 - n.low_y[xb] : n.low_y[xb]) * kUnit;
        return 4.0f * px * py;
    }
    struct Energy {
        double e[4] = {0.0, 0.0, 0.0, 0.0};
        double sum() const { return e[0] + e[1] + e[2] + e[3]; }
    };
    int depth_below(std::uint32_t node) const;

    std::vector<Node> nodes_;
    std::vector<Energy> energy_;  // one per node
};

}  // namespace sweeptrace
