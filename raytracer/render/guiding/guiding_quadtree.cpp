#include "raytracer/render/guiding/guiding_quadtree.hpp"

#include <algorithm>
#include <cmath>

#include "raytracer/geometry/shapes/uv_maps.hpp"
#include "raytracer/render/sampling/sampling.hpp"

namespace sweeptrace {

namespace {

// The density on the sphere of a density 1 on the square: the map preserves area, 4 pi to 1.
constexpr float kSquareToSphere = 1.0f / (4.0f * kPi);

// A probability in units of 1/65535.
std::uint16_t quantize(double p) { return static_cast<std::uint16_t>(std::lround(std::clamp(p, 0.0, 1.0) * 65535.0)); }

// Picks the half of [0, 1) holding `u` when the lower half has probability `p_low`, and
// stretches u back over [0, 1) inside it (about one bit of u used per level, as a 2D warp does;
// 24-bit uniforms leave ~17 bits inside a leaf at depth 7, far finer than any pixel resolves).
bool pick_upper(float& u, float p_low) {
    if (u < p_low) {
        u = std::min(u / p_low, kBelowOne);
        return false;
    }
    u = std::min((u - p_low) / (1.0f - p_low), kBelowOne);
    return true;
}

}  // namespace

glm::vec2 direction_to_square(const glm::vec3& dir) {
    const float u = std::clamp(0.5f * (dir.z + 1.0f), 0.0f, 1.0f);
    const float v = uv_maps::longitude(dir.x, dir.y);  // the azimuth about +z
    // Both ends at 1 are the same places as 0's neighbourhood, mapped into the last cell.
    return {std::min(u, kBelowOne), std::min(v, kBelowOne)};
}

glm::vec3 square_to_direction(const glm::vec2& p) {
    const float z = 2.0f * p.x - 1.0f;
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = 2.0f * kPi * p.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

DirectionalQuadtree::DirectionalQuadtree() : nodes_(1), energy_(1) {}

void DirectionalQuadtree::record(const glm::vec3& dir, float value) { record_square(direction_to_square(dir), value); }

void DirectionalQuadtree::record_square(const glm::vec2& p, float value) {
    double x = p.x, y = p.y;
    std::uint32_t node = 0;
    for (;;) {
        const int xb = x >= 0.5 ? 1 : 0, yb = y >= 0.5 ? 1 : 0;
        const int q = xb + 2 * yb;
        energy_[node].e[q] += value;
        const std::uint32_t next = nodes_[node].child[q];
        if (next == 0) return;
        x = 2.0 * x - xb;  // exact: scaling by 2 and subtracting 0 or 1
        y = 2.0 * y - yb;
        node = next;
    }
}

double DirectionalQuadtree::total() const { return energy_[0].sum(); }

void DirectionalQuadtree::freeze() {
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
        const double sum = energy_[i].sum();
        if (!(sum > 0.0)) continue;  // never reached: its parent's quadrant has no energy
        const double* e = energy_[i].e;
        Node& n = nodes_[i];
        n.low_x = quantize((e[0] + e[2]) / sum);
        for (int xb = 0; xb < 2; ++xb) {
            const double column = e[xb] + e[xb + 2];
            // A column with no energy is never picked; any split keeps its density 0.
            n.low_y[xb] = column > 0.0 ? quantize(e[xb] / column) : kHalf;
        }
    }
}

glm::vec3 DirectionalQuadtree::sample(float u1, float u2, float* density) const {
    const glm::vec2 p = sample_square(u1, u2, density);
    if (density != nullptr) *density *= kSquareToSphere;
    return square_to_direction(p);
}

glm::vec2 DirectionalQuadtree::sample_square(float u1, float u2, float* density) const {
    float ux = u1, uy = u2;
    float d = 1.0f;
    float ox = 0.0f, oy = 0.0f, size = 1.0f;  // the cell: powers of two, exact in float
    std::uint32_t node = 0;
    for (;;) {
        const Node& n = nodes_[node];
        // The column by its share, then the quadrant within it; a column with no energy has
        // share exactly 0, so it is never picked (and pick_upper never divides by zero).
        const int xb = pick_upper(ux, float(n.low_x) * kUnit) ? 1 : 0;
        const int yb = pick_upper(uy, float(n.low_y[xb]) * kUnit) ? 1 : 0;
        d *= factor(n, xb, yb);
        size *= 0.5f;
        ox += float(xb) * size;
        oy += float(yb) * size;
        const std::uint32_t next = n.child[xb + 2 * yb];
        if (next == 0) break;
        node = next;
    }
    if (density != nullptr) *density = d;
    return {ox + ux * size, oy + uy * size};
}

float DirectionalQuadtree::pdf(const glm::vec3& dir) const {
    return pdf_square(direction_to_square(dir)) * kSquareToSphere;
}

float DirectionalQuadtree::pdf_square(const glm::vec2& p) const {
    float x = p.x, y = p.y;
    float density = 1.0f;
    std::uint32_t node = 0;
    for (;;) {
        const Node& n = nodes_[node];
        const int xb = x >= 0.5f ? 1 : 0, yb = y >= 0.5f ? 1 : 0;
        const int q = xb + 2 * yb;
        density *= factor(n, xb, yb);
        if (n.child[q] == 0 || density == 0.0f) return density;
        x = 2.0f * x - float(xb);  // exact in float too
        y = 2.0f * y - float(yb);
        node = n.child[q];
    }
}

DirectionalQuadtree DirectionalQuadtree::refined(double threshold, int max_depth) const {
    // Breadth first, so that a node's children are adjacent and the top levels share the first
    // cache lines, which prefetch() loads while the path vertex does other work. (Node order
    // changes no density: sample() and pdf() follow child indices. Only at kMaxNodes does the
    // order choose which nodes exist: breadth first keeps the shallower ones.)
    struct Pending {
        std::uint32_t out_node;
        int old_node;  // the node of this tree in the same place, or -1 where this tree had a leaf
        double energy[4];
        int depth;
    };
    DirectionalQuadtree out;
    const double total_energy = total();
    std::vector<Pending> queue;
    queue.push_back(Pending{0, 0, {}, 1});
    std::copy(energy_[0].e, energy_[0].e + 4, queue[0].energy);
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const Pending p = queue[head];  // a copy: push_back may move the queue
        for (int q = 0; q < 4; ++q) {
            if (!(total_energy > 0.0) || p.energy[q] / total_energy <= threshold || p.depth >= max_depth ||
                out.nodes_.size() >= kMaxNodes)
                continue;
            const auto child = static_cast<std::uint16_t>(out.nodes_.size());
            out.nodes_.emplace_back();
            out.energy_.emplace_back();
            out.nodes_[p.out_node].child[q] = child;
            const int old_child = p.old_node >= 0 && nodes_[p.old_node].child[q] != 0 ? int(nodes_[p.old_node].child[q]) : -1;
            Pending next{child, old_child, {}, p.depth + 1};
            if (old_child >= 0) std::copy(energy_[old_child].e, energy_[old_child].e + 4, next.energy);
            else std::fill(next.energy, next.energy + 4, 0.25 * p.energy[q]);
            queue.push_back(next);
        }
    }
    return out;
}

void DirectionalQuadtree::prefetch() const {
    const char* base = reinterpret_cast<const char*>(nodes_.data());
    const std::size_t bytes = std::min(nodes_.size() * sizeof(Node), kPrefetchBytes);
    for (std::size_t b = 0; b < bytes; b += 64) __builtin_prefetch(base + b);
}

int DirectionalQuadtree::depth_below(std::uint32_t node) const {
    int d = 0;
    for (const std::uint32_t c : nodes_[node].child)
        if (c != 0) d = std::max(d, depth_below(c));
    return d + 1;
}

int DirectionalQuadtree::depth() const { return depth_below(0); }

}  // namespace sweeptrace
