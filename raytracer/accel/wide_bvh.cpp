#include "raytracer/accel/wide_bvh.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include <glm/common.hpp>

#include "raytracer/accel/sah_cost.hpp"

namespace sweeptrace {
namespace {

class Collapser {
public:
    Collapser(const collision::Bvh& bvh, std::uint32_t max_leaf, WideBvh& out)
        : bvh_(bvh), max_leaf_(max_leaf), out_(out), first_(bvh.nodes.size()), count_(bvh.nodes.size()) {
        // Children come after their parent in the binary array: one backward pass sums ranges.
        for (std::size_t i = bvh.nodes.size(); i-- > 0;) {
            const collision::BvhNode& n = bvh.nodes[i];
            if (n.is_leaf()) {
                first_[i] = n.first;
                count_[i] = n.count;
            } else {
                first_[i] = first_[n.first];
                count_[i] = count_[n.first] + count_[n.first + 1];
            }
        }
    }

    std::uint32_t reference(std::uint32_t b, int depth) {
        if (bvh_.nodes[b].is_leaf() || count_[b] <= max_leaf_) {
            if (count_[b] > max_leaf_) throw std::invalid_argument("collapse_to_wide: binary leaf larger than max_leaf");
            if (first_[b] > wide_ref::max_first) throw std::length_error("collapse_to_wide: too many primitives");
            return wide_ref::leaf(first_[b], count_[b]);
        }
        std::uint32_t children[kWideWidth];
        const int n = open_children(b, children);
        const std::uint8_t axis = sort_children(children, n);
        const std::uint32_t index = static_cast<std::uint32_t>(out_.nodes.size());
        out_.nodes.emplace_back();
        out_.axis.push_back(axis);
        out_.depth = depth > out_.depth ? depth : out_.depth;
        for (int slot = 0; slot < kWideWidth; ++slot) {
            const bool used = slot < n;
            for (int a = 0; a < 3; ++a) {
                out_.nodes[index].box[a][0][slot] = used ? bvh_.nodes[children[slot]].lo[a] : kInf;
                out_.nodes[index].box[a][1][slot] = used ? bvh_.nodes[children[slot]].hi[a] : -kInf;
            }
            // `reference` may grow out_.nodes: index, never hold a reference into it.
            const std::uint32_t ref = used ? reference(children[slot], depth + 1) : wide_ref::empty;
            out_.nodes[index].child[slot] = ref;
        }
        return index;
    }

private:
    static constexpr float kInf = std::numeric_limits<float>::infinity();

    bool openable(std::uint32_t b) const { return !bvh_.nodes[b].is_leaf() && count_[b] > max_leaf_; }

    // Children in the order of their box centres along the axis where those centres spread
    // most (ties: the binary tree's order); returns that axis (WideBvh::axis).
    std::uint8_t sort_children(std::uint32_t* children, int n) const {
        glm::vec3 lo(kInf), hi(-kInf);
        for (int i = 0; i < n; ++i) {
            const glm::vec3 c = centre(children[i]);
            lo = glm::min(lo, c);
            hi = glm::max(hi, c);
        }
        const glm::vec3 spread = hi - lo;
        const int axis = spread.x >= spread.y ? (spread.x >= spread.z ? 0 : 2) : (spread.y >= spread.z ? 1 : 2);
        std::stable_sort(children, children + n,
                         [&](std::uint32_t p, std::uint32_t q) { return centre(p)[axis] < centre(q)[axis]; });
        return static_cast<std::uint8_t>(axis);
    }

    glm::vec3 centre(std::uint32_t b) const { return 0.5f * (bvh_.nodes[b].lo + bvh_.nodes[b].hi); }

    // The binary node's children, opened largest-area first until kWideWidth of them.
    int open_children(std::uint32_t b, std::uint32_t* children) const {
        int n = 0;
        children[n++] = bvh_.nodes[b].first;
        children[n++] = bvh_.nodes[b].first + 1;
        while (n < kWideWidth) {
            int best = -1;
            float best_area = -1.0f;
            for (int i = 0; i < n; ++i) {
                const collision::BvhNode& c = bvh_.nodes[children[i]];
                const float area = collision::Bounds3{c.lo, c.hi}.half_area();
                if (openable(children[i]) && area > best_area) {
                    best = i;
                    best_area = area;
                }
            }
            if (best < 0) break;
            const std::uint32_t opened = children[best];
            children[best] = bvh_.nodes[opened].first;
            children[n++] = bvh_.nodes[opened].first + 1;
        }
        return n;
    }

    const collision::Bvh& bvh_;
    std::uint32_t max_leaf_;
    WideBvh& out_;
    std::vector<std::uint32_t> first_, count_;  // per binary node: its subtree's slot range
};

double score(const WideBvh& tree, std::uint32_t ref, double area) {
    if (wide_ref::is_leaf(ref)) return area * wide_ref::count(ref);
    const WideNode& node = tree.nodes[ref];
    double cost = area;
    for (int i = 0; i < kWideWidth; ++i) {
        if (node.child[i] == wide_ref::empty) continue;
        const glm::vec3 lo(node.box[0][0][i], node.box[1][0][i], node.box[2][0][i]);
        const glm::vec3 hi(node.box[0][1][i], node.box[1][1][i], node.box[2][1][i]);
        cost += score(tree, node.child[i], surface_area(lo, hi));
    }
    return cost;
}

}  // namespace

WideBvh collapse_to_wide(const collision::Bvh& bvh, std::uint32_t max_leaf) {
    if (max_leaf < 1 || max_leaf > wide_ref::max_leaf_count) throw std::invalid_argument("collapse_to_wide: max_leaf must be 1..15");
    WideBvh out;
    if (bvh.nodes.empty()) return out;
    Collapser collapser(bvh, max_leaf, out);
    out.root = collapser.reference(0, 1);
    return out;
}

double sah_cost(const WideBvh& tree) {
    if (tree.nodes.empty()) return wide_ref::count(tree.root);
    glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
    const WideNode& root = tree.nodes[0];
    for (int i = 0; i < kWideWidth; ++i)
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], root.box[a][0][i]);
            hi[a] = std::max(hi[a], root.box[a][1][i]);
        }
    const double area = surface_area(lo, hi);
    return area > 0.0 ? score(tree, tree.root, area) / area : 0.0;
}

}  // namespace sweeptrace
