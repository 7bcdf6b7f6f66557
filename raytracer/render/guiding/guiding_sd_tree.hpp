#pragma once
// The spatial half of path guiding (Müller, Gross, Novák 2017, §3.2): a binary tree over a box
// of space, split at the midpoint along x, y, z in turn, whose leaves each hold two directional
// quadtrees: `sampling`, learned in the previous training iteration and read during a pass, and
// `building`, filled with this iteration's records.
//
// Training (§3.4) runs in iterations of doubling length: iteration k spans 2^k passes of one
// sample per pixel (passes 2^k - 1 .. 2^(k+1) - 2), for kTrainingIterations iterations; later
// passes sample the last guide without recording. What doubles is the number of paths: on an
// image of more than kIterationPaths pixels, iteration k spans 2^k kIterationPaths paths,
// rounded up to whole passes (at least one), so a large image learns the guide as well in fewer
// passes and spends the rest of its time guided and not recording. At its end, building becomes sampling; a
// leaf that received more than kSplitRecords * sqrt(2^k) records splits (repeatedly, assuming its
// records spread evenly) and its children start from copies of its quadtrees; each new building
// quadtree takes the structure its sampling tree's energy asks for (quadrants holding more than
// kQuadtreeThreshold of the energy subdivided, to depth kQuadtreeMaxDepth) with zero energy.
// A leaf's guide is used only where most next-event samples of the iteration found no light
// (kNeeMissShare): a choice of where to guide, so any rule keeps the estimator unbiased. Leaves
// where NEE found the light only count records in the next iteration (no quadtree updates), so
// they learn again, one iteration late, if that changes.
// Where few leaves would guide (kMinGuidedShare), guiding switches itself off after
// kDecisionIteration: a scene whose lights next event estimation finds pays almost nothing for it.
//
// Determinism: the tree changes only between passes, from records merged in a fixed order (the
// renderer adds each tile's records in tile order, each tile's in pixel order), so the guide a
// pass reads does not depend on the thread count. The box is the bounding box of the first
// merged pass's records (min and max do not depend on order either), made a cube and enlarged a
// little; points outside it fall into the nearest leaf.
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "raytracer/render/guiding/guiding_quadtree.hpp"
#include "raytracer/render/guiding/sky_guide.hpp"

namespace sweeptrace {

// One estimate of incident radiance at `point` from direction `dir`: radiance (mean of the
// channels) divided by the density the direction was drawn with, so that records summed over a
// quadrant estimate the radiance integrated over its solid angle.
struct GuideRecord {
    glm::vec3 point{0.0f};
    glm::vec3 dir{0.0f};
    float value = 0.0f;
    std::uint32_t leaf = 0;  // leaf_of(point) in the tree of the pass that made the record
    bool light_sample = false;  // from next event estimation (value 0: it found no light)
    // Next event estimation's sample on the light's square (before the light maps it to a point)
    // and its unweighted estimate, radiance x cos / density: what the light guide learns.
    glm::vec2 light_uv{0.0f};
    float light_value = 0.0f;
    // The part of `value` that came from a sky without a portal along `dir` (a next-event sample
    // of the guided sky, or a BSDF-sampled ray that escaped to it): what the sky guide learns
    // (sky_guide.hpp).
    float sky_value = 0.0f;
};

class GuidingSdTree {
public:
    static constexpr double kSplitRecords = 2000.0;   // c of PPG §3.4
    static constexpr double kQuadtreeThreshold = 0.01;  // rho of PPG §3.4
    static constexpr int kQuadtreeMaxDepth = 20;
    // The light guide's, shallower: NEE's successes concentrate in a small part of the square
    // (a sliver near the horizon for points beside the light), where depth 20 made every
    // descent 20 cache misses (a guided 1024x768 smallpt render 5x slower).
    static constexpr int kLightQuadtreeMaxDepth = 8;
    static constexpr double kLightQuadtreeThreshold = 0.05;
    // The sky guide's (sky_guide.hpp), per leaf: a window seen from a region covers a few percent
    // of the sphere, and a cell of depth 10 is a millionth of it. Cells are split above 3% of the
    // energy rather than 1%: measured on the window room without its portal (160 spp, seeds 7
    // and 8), 0.95x the RMSE in 0.9x the CPU time (the finer tree follows the records' noise).
    static constexpr int kSkyQuadtreeMaxDepth = 10;
    static constexpr double kSkyQuadtreeThreshold = 0.03;
    // The scene's learned exits (SkyExitGuide): learned from every leaf's records at once, so
    // finer (a window is a percent or two of the six faces' square).
    static constexpr int kSkyExitMaxDepth = 12;
    static constexpr double kSkyExitThreshold = 0.01;
    // Training ends after this many iterations (2^k - 1 = 255 passes): recording and merging cost
    // about as much as the guide saves on scenes next event estimation already handles, and the
    // guide gains little from more records once its cells are fine.
    static constexpr int kTrainingIterations = 8;
    static constexpr double kIterationPaths = 16384.0;  // the paths of iteration 0 (at most)
    // A leaf guides only where next event estimation fails more often than this (its light
    // samples blocked or on the wrong side): where NEE finds the light, BSDF sampling is
    // already the right partner for it and the guide would only add its cost. (Judged by
    // energy instead, smallpt's ceiling would be guided too: its light samples reach the cap at
    // grazing angles and carry almost nothing. Measured, 128x96 1024 spp: per-sample error
    // 0.97x, CPU time 1.07x; not worth it.)
    static constexpr double kNeeMissShare = 0.5;
    // At the end of iteration kDecisionIteration (the first pass), guiding switches itself off
    // for the rest of the render when fewer than kMinGuidedShare of the iteration's records fell
    // in leaves that would guide: recording and looking up leaves cost every path vertex, and pay
    // only at the guided ones. (After the first iteration's split every leaf holds the same
    // halved counts, so this is next event estimation's miss share over the whole pass.)
    // Measured shares at iterations 1 / 3 / 5 (96x72): smallpt 1.00 / 0.97 / 0.91, default
    // 0.18 / 0.18 / 0.33, cornell-box 0.10 / 0.06 / 0.11. Decided before any pass is guided: the
    // passes before the decision, guided by a guide learned from one or two passes, cost
    // cornell-box up to 6% at equal time when it came after iteration 3, and with it after
    // iteration 1 (two guided passes) still 15% at T = 1 CPU s (96x96, equal_time.py).
    static constexpr int kDecisionIteration = 0;
    static constexpr double kMinGuidedShare = 0.5;

    // Adds one pass's records, batch by batch in order, to the building quadtrees (the first
    // pass with records also fixes the box).
    void add(const std::vector<std::vector<GuideRecord>>& batches);
    // Call after each completed pass with the number of passes completed so far: at the end of
    // an iteration, the building distribution becomes the sampling one and the tree is refined.
    void end_pass(int completed_passes);
    // The paths one pass traces (the image's pixels); before the first end_pass. 0: 2^k passes.
    void set_paths_per_pass(std::uint64_t paths) { paths_per_pass_ = paths; }
    // The passes iteration k spans.
    long long passes_of_iteration(int k) const;

    // The leaf holding `point` (valid until the next end_pass).
    std::uint32_t leaf_of(const glm::vec3& point) const;
    // The same leaf by the descent from the root, without the grid: what leaf_of is tested against.
    std::uint32_t leaf_of_from_root(const glm::vec3& point) const;
    // The learned distribution of a leaf, or nullptr where nothing was learned yet.
    const DirectionalQuadtree* guide_at(std::uint32_t leaf) const {
        return leaves_[leaf].usable ? &leaves_[leaf].sampling : nullptr;
    }
    const DirectionalQuadtree* guide(const glm::vec3& point) const { return guide_at(leaf_of(point)); }
    // The learned distribution of next event estimation's sample square in a guiding leaf, or
    // nullptr (see light_guide.hpp for how the integrator uses it).
    const DirectionalQuadtree* light_guide_at(std::uint32_t leaf) const {
        return leaves_[leaf].light_usable ? &leaves_[leaf].light_sampling : nullptr;
    }
    // The learned distribution of a sky without a portal seen from a guiding leaf, or nullptr
    // (sky_guide.hpp).
    const DirectionalQuadtree* sky_guide_at(std::uint32_t leaf) const {
        return leaves_[leaf].sky_usable ? &leaves_[leaf].sky_sampling : nullptr;
    }
    // Where the rays that reach that sky leave the box of the first pass's records, for the whole
    // scene, or nullptr (sky_guide.hpp).
    const SkyExitGuide* sky_exit() const { return exit_usable_ ? &exit_sampling_ : nullptr; }

    bool training() const { return !off_ && iterations_done_ < kTrainingIterations; }
    // False once guiding switched itself off (kMinGuidedShare): no leaf guides any more.
    bool active() const { return !off_; }
    std::size_t leaf_count() const { return leaves_.size(); }
    int iterations_done() const { return iterations_done_; }

private:
    struct Node {  // split along axis depth % 3 at the middle of its box
        std::uint32_t child[2] = {0, 0};  // 0: a leaf (node 0 is the root)
        std::uint32_t leaf = 0;           // index into leaves_ when a leaf
        std::uint32_t depth = 0;
    };
    // leaf_of's descent reads the point's position in the box as kCoordBits-bit integers per axis:
    // the node at depth d splits axis d % 3, and the point's side is bit kCoordBits - 1 - d / 3 of
    // that coordinate (exact: no split plane is recomputed in float). The tree is never split
    // deeper than kMaxDepth, which those bits cover.
    static constexpr int kCoordBits = 21;
    static constexpr std::uint32_t kMaxDepth = 3 * kCoordBits;
    // And starts at a grid of kGridBits bits per axis over the box, whose cells are exactly the
    // nodes of depth 3 kGridBits: each cell holds that node, or the leaf above it. The descent's
    // first levels were a chain of dependent loads that missed the cache (5% of a guided render).
    static constexpr int kGridBits = 5;
    void rebuild_grid();
    void quantize(const glm::vec3& point, std::uint32_t q[3]) const;
    // From `node` at `depth` toward q: the leaf, or the node at max_depth above it.
    std::uint32_t descend(std::uint32_t node, std::uint32_t depth, const std::uint32_t q[3],
                          std::uint32_t max_depth = kMaxDepth + 1) const;
    struct Leaf {
        DirectionalQuadtree sampling, building;
        std::uint64_t records = 0;  // in the building tree
        std::uint64_t light_samples = 0, light_misses = 0;  // NEE records among them, and blank ones
        bool usable = false;        // sampling has energy (and is frozen), and NEE misses here
        bool learning = true;       // NEE missed here last iteration: fill `building`
        // Next event estimation's own guide, over the light's sample square: learned wherever the
        // directional one is, from the NEE samples' unweighted estimates.
        DirectionalQuadtree light_sampling, light_building;
        bool light_usable = false;  // usable, and light_sampling has energy
        // Where the sky without a portal is seen from here, learned wherever the directional
        // guide is, from the sky's MIS-weighted estimates.
        DirectionalQuadtree sky_sampling, sky_building;
        bool sky_usable = false;  // usable, and sky_sampling has energy
    };
    void set_box(const std::vector<std::vector<GuideRecord>>& batches);
    void end_iteration(int iteration);
    void split(std::uint32_t node, double threshold);
    // NEE missed in more than kNeeMissShare of the leaf's light samples (or took none): it learns.
    // A leaf that guided NEE last iteration (a light's square or the sky) keeps guiding: its NEE
    // now finds the light because it is guided, and judging it by that would switch the guide
    // off and on in turn.
    static bool misses_nee(const Leaf& leaf) {
        return leaf.light_usable || leaf.sky_usable || leaf.light_samples == 0 ||
               double(leaf.light_misses) > kNeeMissShare * double(leaf.light_samples);
    }
    // The share of this iteration's records in leaves that learn.
    double guided_record_share() const;

    SkyExitGuide exit_sampling_, exit_building_;
    bool exit_usable_ = false;
    glm::vec3 records_lo_{0.0f}, records_hi_{0.0f};  // the first merged pass's records' box
    glm::vec3 lo_{0.0f};
    float coord_scale_ = 0.0f;  // 2^kCoordBits / side of the box
    bool has_box_ = false;
    std::vector<Node> nodes_{Node{}};
    std::vector<std::uint32_t> grid_;  // node per grid cell (empty while the tree is one leaf)
    std::vector<Leaf> leaves_{Leaf{}};
    int iterations_done_ = 0;
    bool off_ = false;
    std::uint64_t paths_per_pass_ = 0;
    long long iteration_end_ = 0;  // completed passes at which the current iteration ends (0: not yet set)
};

}  // namespace sweeptrace
