#include "raytracer/render/guiding/guiding_sd_tree.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/common.hpp>

namespace sweeptrace {

void GuidingSdTree::set_box(const std::vector<std::vector<GuideRecord>>& batches) {
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const std::vector<GuideRecord>& records : batches)
        for (const GuideRecord& r : records) {
            lo = glm::min(lo, r.point);
            hi = glm::max(hi, r.point);
        }
    if (!(lo.x <= hi.x)) return;  // no records yet
    // A cube, so that splitting x, y, z in turn keeps leaves near cubes; 1% margin so that the
    // extreme records are not on the boundary.
    const float side = std::max(1e-3f, 1.01f * std::max(hi.x - lo.x, std::max(hi.y - lo.y, hi.z - lo.z)));
    // The sky's exits are learned on the records' own box, not the cube: a window in a wall at
    // the scene's edge is then where the rays leave, the same place seen from every point.
    records_lo_ = lo;
    records_hi_ = hi;
    lo_ = 0.5f * (lo + hi) - glm::vec3(0.5f * side);
    coord_scale_ = std::ldexp(1.0f, kCoordBits) / side;
    has_box_ = true;
}

std::uint32_t GuidingSdTree::descend(std::uint32_t node, std::uint32_t depth, const std::uint32_t q[3],
                                     std::uint32_t max_depth) const {
    for (;; ++depth) {
        const Node& n = nodes_[node];
        if (n.child[0] == 0 || depth == max_depth) return node;
        const std::uint32_t bit = kCoordBits - 1 - depth / 3;
        node = n.child[(q[depth % 3] >> bit) & 1u];
    }
}

void GuidingSdTree::quantize(const glm::vec3& point, std::uint32_t q[3]) const {
    constexpr std::uint32_t kLast = (1u << kCoordBits) - 1;
    for (int a = 0; a < 3; ++a) {
        // Outside the box (or NaN) clamps to the nearest cell: the nearest leaf.
        const float f = (point[a] - lo_[a]) * coord_scale_;
        q[a] = f >= 0.0f ? (f < float(kLast) ? static_cast<std::uint32_t>(f) : kLast) : 0u;
    }
}

std::uint32_t GuidingSdTree::leaf_of(const glm::vec3& point) const {
    if (grid_.empty()) return 0;  // one leaf (and perhaps no box yet)
    std::uint32_t q[3];
    quantize(point, q);
    constexpr int kShift = kCoordBits - kGridBits;
    const std::uint32_t cell = (q[0] >> kShift) | ((q[1] >> kShift) << kGridBits) | ((q[2] >> kShift) << (2 * kGridBits));
    const std::uint32_t start = grid_[cell];
    return nodes_[descend(start, nodes_[start].depth, q)].leaf;
}

std::uint32_t GuidingSdTree::leaf_of_from_root(const glm::vec3& point) const {
    if (nodes_[0].child[0] == 0) return 0;
    std::uint32_t q[3];
    quantize(point, q);
    return nodes_[descend(0, 0, q)].leaf;
}

void GuidingSdTree::rebuild_grid() {
    constexpr std::uint32_t kCells = 1u << kGridBits;
    constexpr std::uint32_t kGridDepth = 3 * kGridBits;
    grid_.assign(std::size_t(kCells) * kCells * kCells, 0);
    for (std::uint32_t cell = 0; cell < grid_.size(); ++cell) {
        const std::uint32_t q[3] = {(cell & (kCells - 1)) << (kCoordBits - kGridBits),
                                    ((cell >> kGridBits) & (kCells - 1)) << (kCoordBits - kGridBits),
                                    (cell >> (2 * kGridBits)) << (kCoordBits - kGridBits)};
        grid_[cell] = descend(0, 0, q, kGridDepth);
    }
}

void GuidingSdTree::add(const std::vector<std::vector<GuideRecord>>& batches) {
    if (!has_box_) {
        set_box(batches);
        if (!has_box_) return;
        // The sky guides' first structures: even cells (a 256th of the sphere, a 32nd of a face),
        // not quadrants, so that what the first pass teaches from the few BSDF rays that escaped
        // already aims next event estimation at the opening rather than at a quarter of the sphere.
        DirectionalQuadtree even;
        for (int q = 0; q < 4; ++q) even.record_square(glm::vec2(0.25f + 0.5f * float(q & 1), 0.25f + 0.5f * float(q >> 1)), 1.0f);
        const DirectionalQuadtree structure = even.refined(0.01, kSkyQuadtreeMaxDepth);
        leaves_[0].sky_building = structure;
        exit_building_.start(records_lo_, records_hi_, structure);
    }
    for (const std::vector<GuideRecord>& records : batches)
        for (const GuideRecord& r : records) {
            Leaf& leaf = leaves_[r.leaf];
            ++leaf.records;
            if (r.light_sample) {
                ++leaf.light_samples;
                if (!(r.value > 0.0f)) ++leaf.light_misses;
            }
            if (r.value > 0.0f && leaf.learning) leaf.building.record(r.dir, r.value);
            if (r.light_value > 0.0f && leaf.learning) leaf.light_building.record_square(r.light_uv, r.light_value);
            if (r.sky_value > 0.0f && leaf.learning) leaf.sky_building.record(r.dir, r.sky_value);
            if (r.sky_value > 0.0f) exit_building_.record(r.point, r.dir, r.sky_value);
        }
}

long long GuidingSdTree::passes_of_iteration(int k) const {
    const double passes = std::ldexp(1.0, k);
    if (double(paths_per_pass_) <= kIterationPaths) return static_cast<long long>(passes);
    return std::max(1ll, static_cast<long long>(std::ceil(passes * kIterationPaths / double(paths_per_pass_))));
}

void GuidingSdTree::end_pass(int completed_passes) {
    if (!training()) return;
    if (iteration_end_ == 0) iteration_end_ = passes_of_iteration(0);
    if (completed_passes < iteration_end_) return;
    end_iteration(iterations_done_);
    ++iterations_done_;
    iteration_end_ += passes_of_iteration(iterations_done_);
}

void GuidingSdTree::split(std::uint32_t node, double threshold) {
    const std::uint32_t leaf = nodes_[node].leaf;
    if (nodes_[node].child[0] != 0 || nodes_[node].depth >= kMaxDepth || double(leaves_[leaf].records) <= threshold)
        return;
    // The records are assumed to spread evenly over the two halves (PPG §3.4).
    leaves_[leaf].records /= 2;
    leaves_[leaf].light_samples /= 2;
    leaves_[leaf].light_misses /= 2;
    Leaf copy = leaves_[leaf];
    leaves_.push_back(std::move(copy));
    const auto other = static_cast<std::uint32_t>(leaves_.size() - 1);
    const auto first = static_cast<std::uint32_t>(nodes_.size());
    const std::uint32_t depth = nodes_[node].depth + 1;
    nodes_.push_back(Node{{0, 0}, leaf, depth});
    nodes_.push_back(Node{{0, 0}, other, depth});
    nodes_[node].child[0] = first;
    nodes_[node].child[1] = first + 1;
    split(first, threshold);
    split(first + 1, threshold);
}

double GuidingSdTree::guided_record_share() const {
    double all = 0.0, guided = 0.0;
    for (const Leaf& leaf : leaves_) {
        all += double(leaf.records);
        if (misses_nee(leaf)) guided += double(leaf.records);
    }
    return all > 0.0 ? guided / all : 0.0;
}

void GuidingSdTree::end_iteration(int iteration) {
    const double threshold = kSplitRecords * std::sqrt(std::ldexp(1.0, iteration));
    const std::size_t nodes = nodes_.size();
    for (std::uint32_t n = 0; n < nodes; ++n) split(n, threshold);
    if (nodes_.size() > 1) rebuild_grid();
    if (iteration == kDecisionIteration && guided_record_share() < kMinGuidedShare) {
        off_ = true;
        for (Leaf& leaf : leaves_) leaf.usable = leaf.light_usable = leaf.sky_usable = false;
        return;
    }
    exit_sampling_ = std::move(exit_building_);
    exit_sampling_.freeze();
    exit_usable_ = exit_sampling_.total() > 0.0;
    exit_building_ = exit_sampling_.refined(kSkyExitThreshold, kSkyExitMaxDepth);
    for (Leaf& leaf : leaves_) {
        leaf.sampling = std::move(leaf.building);
        leaf.sampling.freeze();
        leaf.learning = misses_nee(leaf);
        leaf.usable = leaf.learning && leaf.sampling.total() > 0.0;
        leaf.light_sampling = std::move(leaf.light_building);
        leaf.light_sampling.freeze();
        leaf.light_usable = leaf.usable && leaf.light_sampling.total() > 0.0;
        leaf.light_building = leaf.light_sampling.refined(kLightQuadtreeThreshold, kLightQuadtreeMaxDepth);
        leaf.sky_sampling = std::move(leaf.sky_building);
        leaf.sky_sampling.freeze();
        leaf.sky_usable = leaf.usable && leaf.sky_sampling.total() > 0.0;
        leaf.sky_building = leaf.sky_sampling.refined(kSkyQuadtreeThreshold, kSkyQuadtreeMaxDepth);
        leaf.light_samples = leaf.light_misses = 0;
        leaf.building = leaf.sampling.refined(kQuadtreeThreshold, kQuadtreeMaxDepth);
        leaf.records = 0;
    }
}


}  // namespace sweeptrace
