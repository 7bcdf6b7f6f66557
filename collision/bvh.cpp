// Binned SAH build (Wald, "On fast construction of SAH-based bounding volume hierarchies", 2007):
// at each node the primitives' centroids are dropped into `bins` equal slices per axis, and the
// cheapest of the bins - 1 planes per axis by the surface area heuristic
//     cost(split) = traversal_cost + intersection_cost * (A_left N_left + A_right N_right) / A_node
// is compared against making a leaf (intersection_cost * N). Ranges whose centroids coincide
// (no plane separates them) or that lie deeper than the SAH depth limit are split at the
// object median instead, which bounds the depth (see Bvh::max_depth).
// Rounding plays no part in correctness here: boxes are unions of the input boxes (min/max are
// exact), and the binning only chooses where to split.
#include "collision/bvh.hpp"
#include "collision/finite.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace collision {
namespace {

constexpr int kSahDepthLimit = 48;
constexpr int kMaxBins = 64;

struct Bin {
    Bounds3 box;
    std::uint32_t count = 0;
};

struct Split {
    int axis = -1;  // -1: no plane separates the centroids
    int bin = 0;    // primitives in bins [0, bin] go left
    float weighted_area = std::numeric_limits<float>::infinity();  // A_left N_left + A_right N_right
};

// Bin of centroid coordinate c in [lo, lo + bins / scale]; the clamp catches c at the top end,
// where rounding can give `bins`.
inline int bin_of(float c, float lo, float scale, int bins) {
    const int b = static_cast<int>((c - lo) * scale);
    return std::min(b, bins - 1);
}

class Builder {
public:
    Builder(std::span<const Bounds3> boxes, std::span<const glm::vec3> centroids, const BvhBuildOptions& options,
            Bvh& out)
        : boxes_(boxes), centroids_(centroids), options_(options), out_(out),
          bins_(std::clamp(options.bins, 2, kMaxBins)),
          max_leaf_(static_cast<std::uint32_t>(std::max(options.max_leaf_size, 1))) {}

    void build() {
        const auto n = static_cast<std::uint32_t>(boxes_.size());
        out_.prim_indices.resize(n);
        for (std::uint32_t i = 0; i < n; ++i) out_.prim_indices[i] = i;
        if (n == 0) return;
        out_.nodes.reserve(2 * static_cast<std::size_t>(n) - 1);
        out_.nodes.push_back(BvhNode{});
        struct Task {
            std::uint32_t node, begin, end;
            int depth;
        };
        std::vector<Task> tasks{{0, 0, n, 0}};
        while (!tasks.empty()) {
            const Task task = tasks.back();
            tasks.pop_back();
            out_.depth = std::max(out_.depth, task.depth);
            const std::uint32_t mid = split_range(task.node, task.begin, task.end, task.depth);
            if (mid == task.begin) continue;  // made a leaf
            const auto left = static_cast<std::uint32_t>(out_.nodes.size());
            out_.nodes[task.node].first = left;
            out_.nodes[task.node].count = 0;
            out_.nodes.resize(out_.nodes.size() + 2);
            tasks.push_back({left + 1, mid, task.end, task.depth + 1});
            tasks.push_back({left, task.begin, mid, task.depth + 1});
        }
        out_.nodes.shrink_to_fit();
    }

private:
    // Sets the node's bounds; returns where the range splits, or `begin` after making it a leaf.
    std::uint32_t split_range(std::uint32_t node_index, std::uint32_t begin, std::uint32_t end, int depth) {
        std::uint32_t* idx = out_.prim_indices.data();
        Bounds3 box, centroid_box;
        for (std::uint32_t i = begin; i < end; ++i) {
            box.extend(boxes_[idx[i]]);
            centroid_box.extend(centroids_[idx[i]]);
        }
        BvhNode& node = out_.nodes[node_index];
        node.lo = box.lo;
        node.hi = box.hi;
        node.first = begin;
        node.count = end - begin;
        const std::uint32_t count = end - begin;
        if (count == 1) return begin;

        if (depth < kSahDepthLimit) {
            const Split split = best_split(begin, end, centroid_box);
            if (split.axis >= 0) {
                const float leaf_cost = options_.intersection_cost * static_cast<float>(count);
                const float split_cost =
                    options_.traversal_cost + options_.intersection_cost * split.weighted_area / box.half_area();
                // A flat parent box (area 0) makes split_cost NaN: no evidence a split helps.
                if (!(split_cost < leaf_cost) && count <= max_leaf_) return begin;
                const float lo = centroid_box.lo[split.axis];
                const float scale = bins_ / (centroid_box.hi[split.axis] - lo);
                const std::uint32_t* mid = std::partition(idx + begin, idx + end, [&](std::uint32_t p) {
                    return bin_of(centroids_[p][split.axis], lo, scale, bins_) <= split.bin;
                });
                return static_cast<std::uint32_t>(mid - idx);
            }
        }
        if (count <= max_leaf_) return begin;
        return median_split(begin, end, centroid_box);
    }

    Split best_split(std::uint32_t begin, std::uint32_t end, const Bounds3& centroid_box) const {
        const std::uint32_t* idx = out_.prim_indices.data();
        std::array<std::array<Bin, kMaxBins>, 3> bins{};
        std::array<float, 3> scale{};
        std::array<bool, 3> usable{};
        for (int a = 0; a < 3; ++a) {
            const float extent = centroid_box.hi[a] - centroid_box.lo[a];
            scale[a] = bins_ / extent;
            usable[a] = extent > 0.0f && std::isfinite(scale[a]);
        }
        for (std::uint32_t i = begin; i < end; ++i) {
            const std::uint32_t p = idx[i];
            for (int a = 0; a < 3; ++a) {
                if (!usable[a]) continue;
                Bin& bin = bins[a][bin_of(centroids_[p][a], centroid_box.lo[a], scale[a], bins_)];
                bin.box.extend(boxes_[p]);
                ++bin.count;
            }
        }
        Split best;
        std::array<float, kMaxBins> right_weighted{};
        for (int a = 0; a < 3; ++a) {
            if (!usable[a]) continue;
            // right_weighted[k] = A * N of bins [k, bins_), swept from the right.
            Bounds3 right;
            std::uint32_t right_count = 0;
            for (int k = bins_ - 1; k > 0; --k) {
                right.extend(bins[a][k].box);
                right_count += bins[a][k].count;
                right_weighted[k] = right_count ? right.half_area() * static_cast<float>(right_count) : -1.0f;
            }
            Bounds3 left;
            std::uint32_t left_count = 0;
            for (int k = 1; k < bins_; ++k) {
                left.extend(bins[a][k - 1].box);
                left_count += bins[a][k - 1].count;
                if (left_count == 0 || right_weighted[k] < 0.0f) continue;
                const float cost = left.half_area() * static_cast<float>(left_count) + right_weighted[k];
                if (cost < best.weighted_area) best = Split{a, k - 1, cost};
            }
        }
        return best;
    }

    std::uint32_t median_split(std::uint32_t begin, std::uint32_t end, const Bounds3& centroid_box) {
        const glm::vec3 extent = centroid_box.hi - centroid_box.lo;
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
        std::uint32_t* idx = out_.prim_indices.data();
        const std::uint32_t mid = begin + (end - begin) / 2;
        // Ties broken by index so the result does not depend on the algorithm's internal order.
        std::nth_element(idx + begin, idx + mid, idx + end, [&](std::uint32_t p, std::uint32_t q) {
            const float cp = centroids_[p][axis], cq = centroids_[q][axis];
            return cp < cq || (cp == cq && p < q);
        });
        return mid;
    }

    std::span<const Bounds3> boxes_;
    std::span<const glm::vec3> centroids_;
    const BvhBuildOptions& options_;
    Bvh& out_;
    int bins_;
    std::uint32_t max_leaf_;
};

}  // namespace

Bvh build_bvh(std::span<const Bounds3> boxes, std::span<const glm::vec3> centroids, const BvhBuildOptions& options) {
    if (boxes.size() != centroids.size())
        throw std::invalid_argument("build_bvh: boxes and centroids differ in length");
    if (boxes.size() >= std::numeric_limits<std::uint32_t>::max())
        throw std::invalid_argument("build_bvh: more than 2^32 - 2 primitives");
    for (std::size_t i = 0; i < boxes.size(); ++i)
        if (!finite(boxes[i].lo) || !finite(boxes[i].hi) || !finite(centroids[i]))
            throw std::invalid_argument("build_bvh: primitive " + std::to_string(i) + " has a non-finite box or centroid");
    Bvh bvh;
    Builder(boxes, centroids, options, bvh).build();
    return bvh;
}

}  // namespace collision
