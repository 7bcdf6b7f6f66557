#include "raytracer/render/guiding_sd_tree.hpp"

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
    size_ = glm::vec3(side);
    lo_ = 0.5f * (lo + hi) - 0.5f * size_;
    has_box_ = true;
}

std::uint32_t GuidingSdTree::leaf_of(const glm::vec3& point) const {
    if (nodes_[0].child[0] == 0) return 0;  // one leaf (and perhaps no box yet)
    glm::vec3 lo = lo_, size = size_;
    std::uint32_t node = 0;
    for (int depth = 0;; ++depth) {
        const Node& n = nodes_[node];
        if (n.child[0] == 0) return n.leaf;
        const int axis = depth % 3;
        size[axis] *= 0.5f;
        const float mid = lo[axis] + size[axis];
        const int side = point[axis] >= mid ? 1 : 0;
        if (side) lo[axis] = mid;
        node = n.child[side];
    }
}

void GuidingSdTree::add(const std::vector<std::vector<GuideRecord>>& batches) {
    if (!has_box_) set_box(batches);
    if (!has_box_) return;
    for (const std::vector<GuideRecord>& records : batches)
        for (const GuideRecord& r : records) {
            Leaf& leaf = leaves_[r.leaf];
            ++leaf.records;
            if (r.light_sample) {
                ++leaf.light_samples;
                if (!(r.value > 0.0f)) ++leaf.light_misses;
            }
            if (r.value > 0.0f && leaf.learning) leaf.building.record(r.dir, r.value);
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
    if (nodes_[node].child[0] != 0 || double(leaves_[leaf].records) <= threshold) return;
    // The records are assumed to spread evenly over the two halves (PPG §3.4).
    leaves_[leaf].records /= 2;
    leaves_[leaf].light_samples /= 2;
    leaves_[leaf].light_misses /= 2;
    Leaf copy = leaves_[leaf];
    leaves_.push_back(std::move(copy));
    const auto other = static_cast<std::uint32_t>(leaves_.size() - 1);
    const auto first = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back(Node{{0, 0}, leaf});
    nodes_.push_back(Node{{0, 0}, other});
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
    if (iteration == kDecisionIteration && guided_record_share() < kMinGuidedShare) {
        off_ = true;
        for (Leaf& leaf : leaves_) leaf.usable = false;
        return;
    }
    for (Leaf& leaf : leaves_) {
        leaf.sampling = std::move(leaf.building);
        leaf.sampling.freeze();
        leaf.learning = misses_nee(leaf);
        leaf.usable = leaf.learning && leaf.sampling.total() > 0.0;
        leaf.light_samples = leaf.light_misses = 0;
        leaf.building = leaf.sampling.refined(kQuadtreeThreshold, kQuadtreeMaxDepth);
        leaf.records = 0;
    }
}


}  // namespace sweeptrace
