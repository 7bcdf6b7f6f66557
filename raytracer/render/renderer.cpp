#include "raytracer/render/renderer.hpp"

#include "raytracer/input_error.hpp"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "collision/finite.hpp"
#include "raytracer/render/adaptive_sampling.hpp"
#include "raytracer/render/camera.hpp"
#include "raytracer/render/film/film_splats.hpp"
#include "raytracer/render/guiding/guiding_sd_tree.hpp"
#include "raytracer/render/integrators/bdpt.hpp"
#include "raytracer/render/integrators/path.hpp"
#include "raytracer/render/integrators/vcm.hpp"
#include "raytracer/render/lights/lights.hpp"
#include "raytracer/render/media/media_nesting.hpp"
#include "raytracer/render/media/medium_model.hpp"
#include "raytracer/render/film/path_forensics.hpp"
#include "raytracer/render/planted_defect.hpp"
#include "raytracer/render/render_tiles.hpp"
#include "raytracer/render/film/sample_features.hpp"
#include "raytracer/render/sampling/sampler.hpp"

namespace sweeptrace {

namespace {

// The render runs in passes of one sample per pixel over the whole image. A cancel request
// abandons the pass in flight, so the returned image always holds the same number of samples in
// every pixel (completed_spp), never a patchwork of tiles with more samples than others.
class PassRenderer {
public:
    PassRenderer(const Scene& scene, const Accel& accel, const RenderOptions& opt, PlantedDefect defect)
        : opt_(opt),
          clamp_sample_(scene.film.clamp_sample),
          budget_(opt.budget_clock, opt.time_budget),
          width_(scene.film.width),
          height_(scene.film.height),
          tiles_x_((width_ + kRenderTileSize - 1) / kRenderTileSize),
          tiles_y_((height_ + kRenderTileSize - 1) / kRenderTileSize),
          lights_(scene, defect),
          camera_(scene.camera, width_, height_, scene.film.filter),
          integrator_(scene, accel, lights_, opt.max_depth, opt.sampling, defect, opt.roulette),
          bdpt_(scene, accel, lights_, camera_, opt.max_depth, defect, opt.roulette,
                opt.sampling == Sampling::LightTracing),
          splat_footprint_(camera_.filter(), scene.film.filter.radius, width_, height_),
          sum_(static_cast<std::size_t>(width_) * height_),
          sum_sq_(sum_.size(), glm::dvec3(0.0)),
          pass_(sum_.size()) {
        if (opt.integrator != IntegratorKind::Path) {
            tile_splats_.resize(static_cast<std::size_t>(std::min(tiles_x_ * tiles_y_, kSplatWaveTiles)));
            splat_sum_.resize(sum_.size());
        }
        bdpt_.set_cancel(opt.cancel);  // a depth-1024 sample takes seconds: it stops inside, its pass dropped
        if (opt.integrator == IntegratorKind::Vcm) vcm_.emplace(scene, accel, camera_, bdpt_, opt.max_depth);
        if (opt.guiding) {
            tile_records_.resize(static_cast<std::size_t>(tiles_x_) * tiles_y_);
            integrator_.set_guide(&guide_);
            guide_.set_paths_per_pass(sum_.size());
        }
        if (opt.forensics != nullptr) opt.forensics->start(width_, height_, kRenderTileSize, lights_);
        if (opt.aovs) {
            feature_sums_.resize(sum_.size());
            pending_.resize(sum_.size() * kAovPendingPasses);
        }
    }

    void run() {
        const int threads = opt_.threads > 0 ? opt_.threads : tbb::task_arena::automatic;
        // TBB caps workers at the core count; an explicit --threads above it is honoured (a
        // user asked for it, and the determinism tests run 3 threads on 2 cores).
        std::optional<tbb::global_control> allow;
        if (opt_.threads > tbb::this_task_arena::max_concurrency())
            allow.emplace(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(opt_.threads));
        tbb::task_arena arena(threads);
        arena.execute([this] {
            if (opt_.adaptive) run_adaptive();
            else run_passes(opt_.first_sample, opt_.spp, opt_.first_sample);
            colour_sum_from_features();
        });
    }

    // Passes of one sample per pixel, sample indices first .. first + passes - 1; returns how many
    // completed. The result keeps those from index keep_from on (completed_spp_ counts them): all
    // of them, but in an adaptive part whose range starts inside the pilot (run_adaptive), whose
    // own passes go to kept_sum_ as well.
    int run_passes(int first, int passes, int keep_from) {
        const int tiles = tiles_x_ * tiles_y_;
        int done = 0;
        for (int s = 0; s < passes; ++s) {
            const int sample = first + s;
            if (stopped(s)) break;
            if (splatting()) start_splat_pass();
            if (vcm_) light_pass(tiles, sample);
            // A cancel is seen per sample (render_tile, light_pass) and inside bdpt's and vcm's
            // strategy loops, so a signal is honoured within a fraction of a sample however long a
            // pass takes; the pass it cut short is dropped.
            const bool abandoned = cancelled() || !run_tiles(tiles, [&](int t) {
                if (stopped(s) || !render_tile(t, sample)) return false;
                tiles_done_.fetch_add(1, std::memory_order_relaxed);
                return true;
            });
            // A cancel during the pass, even after its last tile started, may have cut a sample short
            // inside the integrator (bdpt's strategy loops): the pass is dropped whole.
            if (abandoned || cancelled()) {
                if (opt_.forensics != nullptr) opt_.forensics->drop_pass();
                break;
            }
            if (splatting()) add_splat_sums();
            if (opt_.guiding && guide_.training()) learn(s + 1);
            accumulate_pass(sample, !kept_sum_.empty() && sample >= keep_from);
            if (opt_.forensics != nullptr) opt_.forensics->end_pass();
            done = s + 1;
            completed_spp_.store(std::max(0, sample + 1 - keep_from), std::memory_order_release);
            samples_done_.fetch_add(static_cast<std::int64_t>(sum_.size()), std::memory_order_relaxed);
        }
        add_pending_features();
        return done;
    }

    // Adaptive sampling (adaptive_sampling.hpp) of the nominal range [A, B) = [first_sample,
    // first_sample + spp) (a whole render: [0, spp)): the pilot's passes in [A, B) as the uniform
    // render's; past the pilot, each pixel's samples between its counts at A and at B. Those
    // need the weights, so a range reaching past the pilot renders all of the pilot first (a farm
    // part pays those 16 passes of the image again) and keeps only its own passes of it. The
    // weights come from the pilot's sums, the same in every part, computed on this thread.
    // After the pilot, passes of kAdaptiveRoundSpp nominal spp (at multiples of it past the pilot,
    // so a --time render stops where a --spp render of its completed_spp does), rendered
    // row-parallel, each pixel's new samples in index order straight after its earlier ones (sum
    // and sum of squares continued from the pixel's own, so they are the very numbers a uniform
    // render of n_p samples gives). A pass cut short by the time budget or a cancel is dropped
    // whole: every pixel keeps its count from the passes before.
    void run_adaptive() {
        const int a = opt_.first_sample, b = opt_.first_sample + opt_.spp;
        if (b <= kAdaptivePilotSpp) {  // the pilot alone: the uniform render's passes
            run_passes(a, opt_.spp, a);
            return;
        }
        if (a > 0 && a < kAdaptivePilotSpp) {
            kept_sum_.assign(sum_.size(), PixelSum{});
            kept_sq_.assign(sum_.size(), glm::dvec3(0.0));
            if (opt_.aovs) kept_features_.assign(sum_.size(), FeatureSums{});
        }
        const bool pilot_done = run_passes(0, kAdaptivePilotSpp, a) == kAdaptivePilotSpp;
        if (pilot_done)
            weights_ = adaptive_pixel_weights(AdaptiveTiles(width_, height_), opt_.adaptive_error, sum_, sum_sq_, kAdaptivePilotSpp);
        if (a > 0) {  // from here on the sums are the part's own: its passes of the pilot, or none
            if (kept_sum_.empty()) {
                std::fill(sum_.begin(), sum_.end(), PixelSum{});
                std::fill(sum_sq_.begin(), sum_sq_.end(), glm::dvec3(0.0));
                std::fill(feature_sums_.begin(), feature_sums_.end(), FeatureSums{});
            } else {
                sum_.swap(kept_sum_);
                sum_sq_.swap(kept_sq_);
                feature_sums_.swap(kept_features_);
                kept_sum_ = {};
                kept_sq_ = {};
                kept_features_ = {};
            }
        }
        if (!pilot_done) return;  // a uniform image of the pilot passes finished
        counts_.assign(sum_.size(), std::max(0, kAdaptivePilotSpp - a));
        round_sum_.resize(sum_.size());
        round_sq_.resize(sum_.size());
        round_features_.resize(feature_sums_.size());
        const std::int64_t t_end = b - kAdaptivePilotSpp;
        for (std::int64_t t = std::max(a, kAdaptivePilotSpp) - kAdaptivePilotSpp; t < t_end;) {
            const std::int64_t next = std::min(t_end, (t / kAdaptiveRoundSpp + 1) * kAdaptiveRoundSpp);
            if (stopped(1)) break;
            // Tasks of one image row each, not 16x16 tiles: a pass's counts are uneven, and a
            // thread left waiting on one heavy tile at the pass's end burns the CPU budget.
            std::atomic<bool> abandoned{false};
            tbb::parallel_for(tbb::blocked_range<int>(0, height_, 1), [&](const tbb::blocked_range<int>& r) {
                for (int y = r.begin(); y < r.end(); ++y) {
                    if (stopped(1) || !render_round_row(y, t, next)) {
                        abandoned.store(true, std::memory_order_relaxed);
                        return;
                    }
                }
            });
            if (abandoned.load() || cancelled()) break;
            for (std::size_t i = 0; i < sum_.size(); ++i) {
                const auto more = static_cast<int>(adaptive_count(weights_[i], next) - adaptive_count(weights_[i], t));
                if (more == 0) continue;
                sum_[i] = round_sum_[i];
                sum_sq_[i] = round_sq_[i];
                if (!feature_sums_.empty()) feature_sums_[i] = round_features_[i];
                counts_[i] += more;
            }
            t = next;
            completed_spp_.store(static_cast<int>(kAdaptivePilotSpp + t - a), std::memory_order_release);
        }
    }

    // Tiles finished over all passes, or the budget's time spent: both only grow, so progress
    // never steps back.
    RenderProgress progress() const {
        const double total = static_cast<double>(tiles_x_) * tiles_y_ * opt_.spp;
        RenderProgress p;
        // Adaptive passes are counted in samples (their tiles hold different counts); a part
        // reaching past the pilot renders the pilot's passes before its range too.
        const int a = opt_.first_sample, b = opt_.first_sample + opt_.spp;
        const double work = static_cast<double>(opt_.spp) + (b > kAdaptivePilotSpp ? std::min(a, kAdaptivePilotSpp) : 0);
        const double done = opt_.adaptive ? static_cast<double>(samples_done_.load(std::memory_order_relaxed)) /
                                                (static_cast<double>(sum_.size()) * work)
                                          : static_cast<double>(tiles_done_.load(std::memory_order_relaxed)) / total;
        p.fraction = std::max(budget_.fraction(), std::min(1.0, done));
        p.completed_spp = completed_spp_.load(std::memory_order_acquire);
        p.seconds = budget_.elapsed();
        p.seconds_left = budget_.left();
        return p;
    }

    // Called once, last: the sums move into the result rather than being copied (48 bytes a pixel).
    RenderResult result(double seconds) {
        RenderResult res;
        res.image = Image(width_, height_);
        res.variance = Image(width_, height_);
        const int spp = completed_spp_.load();
        std::uint64_t samples = 0;
        for (std::size_t i = 0; i < sum_.size(); ++i) {
            // Each pixel's own count: spp, or under adaptive sampling its n_p.
            const int n = counts_.empty() ? spp : counts_[i];
            samples += static_cast<std::uint64_t>(n);
            if (n < 1) continue;
            res.image.pixels[i] = mean_of(sum_[i], n);
            const glm::dvec3 mean = sum_value(sum_[i]) / double(n);
            if (n > 1) {
                const glm::dvec3 var = glm::max(sum_sq_[i] - double(n) * mean * mean, glm::dvec3(0.0)) / double(n - 1);
                res.variance.pixels[i] = glm::vec3(var / double(n));
            }
        }
        res.stats.seconds = seconds;
        res.stats.completed_spp = spp;
        res.stats.samples = samples;
        res.stats.rays = rays_.load();
        res.stats.nonfinite_samples = nonfinite_.load();
        res.stats.clamped_samples = clamped_.load();
        res.stats.cancelled = spp < opt_.spp && cancelled();
        res.stats.budget_spent = spp < opt_.spp && !res.stats.cancelled;
        res.sums = std::move(sum_);
        res.pixel_samples = std::move(counts_);
        res.features = std::move(feature_sums_);
        return res;
    }

private:
    // Adds the finished pass to the sums. Fixed point (partial_sum.hpp), so the sum of any split
    // into sample ranges is the same integer, and so the same image.
    // `kept`: also to kept_sum_ (an adaptive part's own passes of the pilot, run_adaptive).
    // With AOVs, the pass's colours and features (already in pending_: pending_sample) to the half
    // of its sample index too, and then, but under adaptive sampling, the colour only there
    // (colour_in_features).
    void accumulate_pass(int sample, bool kept) {
        const bool in_features = colour_in_features();
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, sum_.size(), 4096),
                          [&](const tbb::blocked_range<std::size_t>& r) {
                              std::uint64_t clamped = 0;
                              for (std::size_t i = r.begin(); i < r.end(); ++i) {
                                  bool c = false;
                                  if (in_features) c = beyond_sample_limit(pass_[i]);
                                  else add_sample(sum_[i], pass_[i], c);
                                  clamped += c ? 1 : 0;
                                  const glm::dvec3 v(pass_[i]);
                                  sum_sq_[i] += v * v;
                                  if (kept) {
                                      add_sample(kept_sum_[i], pass_[i], c);
                                      kept_sq_[i] += v * v;
                                  }
                              }
                              if (clamped != 0) clamped_.fetch_add(clamped, std::memory_order_relaxed);
                          });
        if (feature_sums_.empty()) return;
        pending_passes_.push_back({sample, kept});
        if (pending_passes_.size() == kAovPendingPasses) add_pending_features();
    }

    // With AOVs, the feature sums hold the colour of every sample as the colour sum takes it (the
    // same fixed-point values, split by the sample's parity), so outside adaptive sampling (whose
    // pilot and rounds read and copy sum_ as they go) the colour is converted and added once, there,
    // and sum_ is their two halves' total, made once all passes are in (colour_sum_from_features):
    // the same integers, so the same image and parts, for a sample's conversion and addition less.
    bool colour_in_features() const { return !feature_sums_.empty() && !opt_.adaptive; }
    void colour_sum_from_features() {
        if (!colour_in_features()) return;
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, sum_.size(), 4096), [&](const tbb::blocked_range<std::size_t>& r) {
            for (std::size_t i = r.begin(); i < r.end(); ++i) {
                sum_[i] = feature_sums_[i].color[0];
                sum_[i] += feature_sums_[i].color[1];
            }
        });
    }

    // The pending passes' colours and features added to the exact feature sums, each pixel's in
    // pass order. A pixel's sums (sizeof(FeatureSums) bytes) are streamed through memory once per
    // kAovPendingPasses passes instead of every pass, and its pending samples once: what made
    // AOVs cheap on a fast scene (cornell-box 320x180, 64 spp: see docs/aovs.md). The sums are
    // integers, so the result is the same whenever they are added.
    void add_pending_features() {
        if (pending_passes_.empty()) return;
        // A pixel's pending samples are one batch for add_feature_samples when their indices are
        // consecutive, as run_passes' passes are.
        static_assert(kAovPendingPasses == kFeatureBatch, "a pixel's pending samples are one batch");
        const std::int64_t first = pending_passes_.front().sample;
        const int n = static_cast<int>(pending_passes_.size());
        bool consecutive = true;
        for (int k = 0; k < n; ++k) consecutive = consecutive && pending_passes_[k].sample == first + k;
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, feature_sums_.size(), 1024),
                          [&](const tbb::blocked_range<std::size_t>& r) {
                              for (std::size_t i = r.begin(); i < r.end(); ++i) {
                                  const FeatureSample* fs = &pending_[i * kAovPendingPasses];
                                  if (consecutive) add_feature_samples(feature_sums_[i], first, fs, n);
                                  for (int k = 0; k < n; ++k) {
                                      const PendingPass& p = pending_passes_[k];
                                      if (!consecutive) add_feature_sample(feature_sums_[i], p.sample, fs[k]);
                                      if (p.kept) add_feature_sample(kept_features_[i], p.sample, fs[k]);
                                  }
                              }
                          });
        pending_passes_.clear();
    }

    // bdpt, vcm: the pass's splats are summed per pixel apart from its camera samples, in the
    // order run_tiles adds them, and join them once the pass is whole (add_splat_sums): the same
    // additions whether the splats come before the camera samples (vcm's light pass) or with them
    // (bdpt), so vcm without merging is bdpt bit for bit.
    bool splatting() const { return !tile_splats_.empty(); }
    void start_splat_pass() {
        std::fill(splat_sum_.begin(), splat_sum_.end(), glm::vec3(0.0f));
        for (std::vector<Splat>& slot : tile_splats_) slot.clear();  // a dropped pass's
    }
    void add_splat_sums() {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pass_.size(), 4096), [&](const tbb::blocked_range<std::size_t>& r) {
            for (std::size_t i = r.begin(); i < r.end(); ++i) {
                pass_[i] += splat_sum_[i];
                if (!feature_sums_.empty()) pending_sample(i).color = pass_[i];
            }
        });
    }
    std::vector<Splat>& splat_slot(int tile) { return tile_splats_[static_cast<std::size_t>(tile % kSplatWaveTiles)]; }

    // tile(t) for every tile, in parallel; false once a tile returns false (a cancel: the pass
    // is dropped). Splatting, the tiles go in waves of kSplatWaveTiles, each wave's splats added
    // to the pass before the next wave starts, so the buffers hold one wave's splats whatever
    // the image's size (film_splats.hpp); the waves are fixed, so the additions are the same for
    // any thread count.
    template <class Tile>
    bool run_tiles(int tiles, Tile&& tile) {
        const int wave = splatting() ? kSplatWaveTiles : tiles;
        for (int w0 = 0; w0 < tiles; w0 += wave) {
            const int w1 = std::min(tiles, w0 + wave);
            std::atomic<bool> abandoned{false};
            tbb::parallel_for(tbb::blocked_range<int>(w0, w1, 1), [&](const tbb::blocked_range<int>& r) {
                for (int t = r.begin(); t < r.end(); ++t)
                    if (!tile(t)) {
                        abandoned.store(true, std::memory_order_relaxed);
                        return;
                    }
            });
            if (abandoned.load()) return false;
            if (splatting()) add_splats(w0, w1);
        }
        return true;
    }

    // The light-tracing splats of tiles [w0, w1), added to the pixels their filter reaches tile by
    // tile in tile order and, within a tile, in the order its samples made them: the same float
    // additions for any thread count, and a pass's values depend only on its sample index, so farm
    // parts merge bit for bit. The pass value of a pixel is then its camera sample plus the sum of
    // every splat of that pass, each pass an independent estimate of the pixel, so the variance of
    // result() (the spread of those values over passes) is that of the whole estimator, splats
    // included.
    void add_splats(int w0, int w1) {
        std::uint64_t nonfinite = 0;
        for (int t = w0; t < w1; ++t) {
            std::vector<Splat>& slot = splat_slot(t);
            for (const Splat& sp : slot)
                splat_footprint_.spread(sp, [&](std::size_t pixel, const glm::vec3& value) {
                    const glm::vec3 v = limited(value);
                    if (collision::finite(v)) splat_sum_[pixel] += v;
                    else ++nonfinite;
                });
            slot.clear();
        }
        if (nonfinite != 0) nonfinite_.fetch_add(nonfinite, std::memory_order_relaxed);
    }

    // vcm: the iteration's light subpaths and their splats, tile by tile (any thread), then its
    // photons into the grid, before any camera subpath of the pass.
    void light_pass(int tiles, int sample) {
        vcm_->begin_iteration(sample, tiles);
        const bool whole = run_tiles(tiles, [&](int t) {
            const int x0 = (t % tiles_x_) * kRenderTileSize, y0 = (t / tiles_x_) * kRenderTileSize;
            const int x1 = std::min(x0 + kRenderTileSize, width_), y1 = std::min(y0 + kRenderTileSize, height_);
            std::uint64_t rays = 0;
            std::vector<Splat>& splats = splat_slot(t);
            bool done = true;
            for (int y = y0; y < y1 && done; ++y)
                for (int x = x0; x < x1; ++x) {
                    if (cancelled()) {  // the pass is dropped (run_passes)
                        done = false;
                        break;
                    }
                    const std::size_t pixel = static_cast<std::size_t>(y) * width_ + x;
                    // The camera sample's shutter time (its subpath sees the scene then), the
                    // light subpath's numbers from a stream of their own.
                    PixelSampler camera(opt_.sampler, opt_.seed, pixel, static_cast<std::uint64_t>(sample));
                    const float time = start_camera_sample(camera).time;
                    PixelSampler light(opt_.sampler, opt_.seed, pixel, static_cast<std::uint64_t>(sample),
                                       SamplerStream::LightSubpath);
                    vcm_->trace_light(t, pixel, time, light, rays, splats);
                }
            vcm_->finish_tile(t);
            rays_.fetch_add(rays, std::memory_order_relaxed);
            return done;
        });
        if (whole && !cancelled()) vcm_->build_grid();
    }

    // A camera sample's first numbers, in the order they are drawn: the film position's offset in
    // the pixel (from the pixel filter), the lens point and the shutter time, drawn only with a
    // shutter, so still scenes take exactly the numbers they did.
    struct CameraStart {
        FilmOffset film;
        glm::vec2 lens;
        float time;
    };
    CameraStart start_camera_sample(PixelSampler& sampler) const {
        const glm::vec2 u_film = sampler.get2d(sample_dim::kFilm);
        const FilmOffset film = camera_.film_offset(u_film.x, u_film.y);
        const glm::vec2 lens = sampler.get2d(sample_dim::kLens);
        const float time = camera_.has_shutter() ? camera_.shutter_fraction(sampler.get1d(sample_dim::kTime)) : 0.0f;
        return {film, lens, time};
    }

    // Training on the pass just finished: tiles merged in tile order, so the guide the next pass
    // reads is the same for any thread count.
    void learn(int completed_passes) {
        guide_.add(tile_records_);
        guide_.end_pass(completed_passes);
    }

    bool cancelled() const { return opt_.cancel != nullptr && opt_.cancel->load(std::memory_order_relaxed); }
    // Pass `pass` is not started, or is dropped: the first pass is kept whatever the budget says.
    bool stopped(int pass) const { return cancelled() || (pass > 0 && budget_.spent()); }

    // False when a cancel cut the tile short (its pass is then dropped).
    bool render_tile(int tile, int sample) {
        const int x0 = (tile % tiles_x_) * kRenderTileSize, y0 = (tile / tiles_x_) * kRenderTileSize;
        const int x1 = std::min(x0 + kRenderTileSize, width_), y1 = std::min(y0 + kRenderTileSize, height_);
        std::uint64_t rays = 0, nonfinite = 0;
        std::vector<GuideRecord>* records =
            opt_.guiding && guide_.training() ? &tile_records_[static_cast<std::size_t>(tile)] : nullptr;
        if (records != nullptr) records->clear();
        const bool bdpt = splatting();
        std::vector<Splat>* splats = bdpt ? &splat_slot(tile) : nullptr;
        // Forensics follow the path integrator's vertices; the command line refuses them with bdpt.
        PathTally tally_storage;
        PathTally* tally = opt_.forensics != nullptr && !bdpt ? &tally_storage : nullptr;
        bool whole = true;
        for (int y = y0; y < y1 && whole; ++y) {
            for (int x = x0; x < x1 && whole; ++x) {
                if (cancelled()) {
                    whole = false;
                    break;
                }
                const std::size_t pixel = static_cast<std::size_t>(y) * width_ + x;
                if (tally != nullptr) tally->begin();
                FeatureSample* pending = feature_sums_.empty() ? nullptr : &pending_sample(pixel);
                const glm::vec3 l = sample_pixel(x, y, sample, rays, nonfinite, records, splats, tally,
                                                 pending != nullptr ? &pending->features : nullptr);
                if (tally != nullptr) opt_.forensics->finish_sample(tile, pixel, *tally, l);
                pass_[pixel] = l;
                // The pass value is final here but for bdpt's and vcm's splats (add_splat_sums):
                // written while the features' line is in cache, not by another sweep of pending_.
                if (pending != nullptr && !bdpt) pending->color = l;
            }
        }
        rays_.fetch_add(rays, std::memory_order_relaxed);
        if (nonfinite != 0) nonfinite_.fetch_add(nonfinite, std::memory_order_relaxed);
        return whole;
    }

    // One camera sample of pixel (x, y): its value after the pixel filter's weight and the film's
    // clamp, a non-finite one counted and made black. With `features`, its features go there.
    glm::vec3 sample_pixel(int x, int y, int sample, std::uint64_t& rays, std::uint64_t& nonfinite,
                           std::vector<GuideRecord>* records, std::vector<Splat>* splats, PathTally* tally,
                           SampleFeatures* features) {
        const std::size_t pixel = static_cast<std::size_t>(y) * width_ + x;
        PixelSampler sampler(opt_.sampler, opt_.seed, pixel, static_cast<std::uint64_t>(sample));
        const auto [film, lens, time] = start_camera_sample(sampler);
        const float fx = static_cast<float>(x) + film.dx;
        const float fy = static_cast<float>(y) + film.dy;
        FeatureRecord record(camera_);
        glm::vec3 l = film.weight * limited(vcm_                 ? vcm_->sample(pixel, fx, fy, lens, time, sampler, rays, features)
                                            : splats != nullptr ? bdpt_.sample(fx, fy, lens, time, sampler, rays, *splats, features)
                                                                : integrator_.radiance(camera_.generate(fx, fy, lens.x, lens.y),
                                                                                       sampler, rays, records, time, tally,
                                                                                       features != nullptr ? &record : nullptr));
        if (features != nullptr && !vcm_ && splats == nullptr) *features = record.features();
        if (!collision::finite(l)) {
            l = glm::vec3(0.0f);
            ++nonfinite;
        }
        return l;
    }

    // An adaptive pass's samples for one image row, the nominal budget past the pilot going from t0
    // to t1: pixel p's samples 16 + adaptive_count(w_p, t0) .. 16 + adaptive_count(w_p, t1) - 1,
    // added to copies of its sums in that order (committed by run_adaptive if the pass completes).
    // False when a cancel cut the row short (its pass is then dropped).
    bool render_round_row(int y, std::int64_t t0, std::int64_t t1) {
        std::uint64_t rays = 0, nonfinite = 0, clamped = 0;
        std::int64_t samples = 0;
        bool whole = true;
        for (int x = 0; x < width_ && whole; ++x) {
            const std::size_t pixel = static_cast<std::size_t>(y) * width_ + x;
            const std::int64_t lo = adaptive_count(weights_[pixel], t0), hi = adaptive_count(weights_[pixel], t1);
            if (hi == lo) continue;
            PixelSum sum = sum_[pixel];
            glm::dvec3 sq = sum_sq_[pixel];
            const bool aovs = !feature_sums_.empty();
            FeatureSums fs = aovs ? feature_sums_[pixel] : FeatureSums{};
            FeatureSample f;
            for (std::int64_t k = lo; k < hi; ++k) {
                if (cancelled()) {
                    whole = false;
                    break;
                }
                const glm::vec3 l = sample_pixel(x, y, static_cast<int>(kAdaptivePilotSpp + k), rays, nonfinite, nullptr,
                                                 nullptr, nullptr, aovs ? &f.features : nullptr);
                f.color = l;
                if (aovs) add_feature_sample(fs, kAdaptivePilotSpp + k, f);
                bool c = false;
                add_sample(sum, l, c);
                clamped += c ? 1 : 0;
                const glm::dvec3 v(l);
                sq += v * v;
            }
            round_sum_[pixel] = sum;
            round_sq_[pixel] = sq;
            if (aovs) round_features_[pixel] = fs;
            samples += hi - lo;
        }
        rays_.fetch_add(rays, std::memory_order_relaxed);
        samples_done_.fetch_add(samples, std::memory_order_relaxed);
        if (nonfinite != 0) nonfinite_.fetch_add(nonfinite, std::memory_order_relaxed);
        if (clamped != 0) clamped_.fetch_add(clamped, std::memory_order_relaxed);
        return whole;
    }

    // film.clamp_sample: the whole sample scaled so its largest component is at most the limit,
    // as pbrt-v4's film does with maxcomponentvalue (before the filter's weight); off, untouched.
    glm::vec3 limited(const glm::vec3& l) const {
        if (!(clamp_sample_ > 0.0f)) return l;
        const float m = std::max(l.x, std::max(l.y, l.z));
        return m > clamp_sample_ ? l * (clamp_sample_ / m) : l;
    }

    const RenderOptions& opt_;
    float clamp_sample_ = 0.0f;
    TimeBudget budget_;
    int width_, height_, tiles_x_, tiles_y_;
    LightSet lights_;
    CameraModel camera_;
    PathIntegrator integrator_;
    BdptIntegrator bdpt_;
    std::optional<VcmIntegrator> vcm_;  // vcm only: it drives bdpt_ per iteration
    SplatFootprint splat_footprint_;
    // bdpt, vcm: the wave in flight's light-tracing splats, a slot per tile of the wave (run_tiles)
    std::vector<std::vector<Splat>> tile_splats_;
    std::vector<glm::vec3> splat_sum_;  // bdpt, vcm: the pass in flight's splats, per pixel
    std::vector<PixelSum> sum_;     // per-pixel exact sum over completed passes
    std::vector<glm::dvec3> sum_sq_;  // per-pixel sum of squares, for the variance
    std::vector<glm::vec3> pass_;   // the pass in flight
    GuidingSdTree guide_;           // read during a pass, trained between passes
    std::vector<std::vector<GuideRecord>> tile_records_;  // the pass in flight's, per tile
    std::vector<int> counts_;              // adaptive: samples per pixel so far (empty: uniform)
    std::vector<double> weights_;          // adaptive: each pixel's weight from the pilot
    std::vector<PixelSum> round_sum_;      // adaptive: the pass in flight's sums, per pixel it samples
    std::vector<glm::dvec3> round_sq_;
    std::vector<PixelSum> kept_sum_;       // adaptive part starting inside the pilot: its own pilot passes
    std::vector<glm::dvec3> kept_sq_;
    // AOVs (opt.aovs; else empty): per pixel, the exact colour and feature sums by half; the
    // colours and features of up to kAovPendingPasses finished passes not yet added to them and
    // of the pass in flight (pixel-major: slot k of pixel i at i * kAovPendingPasses + k, so that
    // add_pending_features reads them as one stream); and the adaptive copies as for the colour
    // above.
    struct PendingPass {
        int sample;
        bool kept;
    };
    std::vector<FeatureSums> feature_sums_;
    std::vector<FeatureSample> pending_;
    // Pixel i's slot in pending_ for the pass in flight.
    FeatureSample& pending_sample(std::size_t i) { return pending_[i * kAovPendingPasses + pending_passes_.size()]; }
    std::vector<PendingPass> pending_passes_;
    std::vector<FeatureSums> round_features_;
    std::vector<FeatureSums> kept_features_;
    std::atomic<int> completed_spp_{0};
    std::atomic<std::int64_t> tiles_done_{0}, samples_done_{0};
    std::atomic<std::uint64_t> rays_{0}, nonfinite_{0}, clamped_{0};
};

}  // namespace

RenderResult render(const Scene& scene, const Accel& accel, const RenderOptions& options) {
    return render_with_planted_defect(scene, accel, options, PlantedDefect::None);
}

RenderResult render_with_planted_defect(const Scene& scene, const Accel& accel, const RenderOptions& options,
                                        PlantedDefect defect) {
    if (scene.film.width < 1 || scene.film.height < 1)
        throw std::invalid_argument("render: film size must be at least 1x1, got " + std::to_string(scene.film.width) +
                                    "x" + std::to_string(scene.film.height));
    if (options.spp < 1) throw std::invalid_argument("render: spp must be at least 1");
    if (options.max_depth < 1) throw std::invalid_argument("render: max_depth must be at least 1");
    if (options.threads < 0) throw std::invalid_argument("render: threads must be >= 0");
    if (options.first_sample < 0 || options.first_sample > std::numeric_limits<int>::max() - options.spp)
        throw std::invalid_argument("render: first_sample must be >= 0 and first_sample + spp fit in an int");
    if (options.sampling != Sampling::NeeMis && options.integrator == IntegratorKind::Vcm)
        throw std::invalid_argument("render: vcm has no sampling variants (light tracing alone is bdpt's)");
    if (options.sampling == Sampling::LightTracing && options.integrator != IntegratorKind::Bdpt)
        throw std::invalid_argument("render: light tracing alone is a bdpt strategy");
    if (options.guiding && options.integrator != IntegratorKind::Path)
        throw std::invalid_argument("render: path guiding is the path integrator's");
    if (!(options.time_budget >= 0.0)) throw std::invalid_argument("render: time_budget must be >= 0 seconds");
    // bdpt and vcm carry at most 2^15 media (light_vertices.hpp), and only their camera subpaths
    // find a medium's emission (render/media/subpath_flight.hpp), which light tracing alone has
    // not: refused here, for every caller, rather than rendered silently wrong.
    if (options.integrator != IntegratorKind::Path) {
        if (options.sampling == Sampling::LightTracing)
            for (const Medium& m : scene.media)
                if (medium_emits(m))
                    throw InputError(scene.source.filename().string() + ": light tracing alone does not render a "
                                     "medium's emission (medium '" + m.name + "' emits): camera subpaths find it");
        if (scene.media.size() > 32767)
            throw InputError(scene.source.filename().string() + ": " + integrator_name(options.integrator) +
                             " renders at most 32767 media (the scene has " + std::to_string(scene.media.size()) +
                             "); render it with --integrator path");
    }
    if (options.adaptive && (options.integrator != IntegratorKind::Path || options.guiding || options.forensics != nullptr))
        throw std::invalid_argument("render: adaptive sampling is the path integrator's, without guiding or forensics");
    // Boundaries that contradict each other are bad input, refused before any sample.
    if (uses_media(scene)) check_media_nesting(scene, accel);

    const auto start = std::chrono::steady_clock::now();
    PassRenderer renderer(scene, accel, options, defect);
    if (!options.progress) {
        renderer.run();
    } else {
        // The work runs on its own thread so that progress is always reported from the caller's.
        std::mutex m;
        std::condition_variable cv;
        bool done = false;
        std::exception_ptr error;
        std::thread worker([&] {
            try {
                renderer.run();
            } catch (...) {
                error = std::current_exception();
            }
            {
                std::lock_guard lock(m);
                done = true;
            }
            cv.notify_all();
        });
        {
            std::unique_lock lock(m);
            while (!cv.wait_for(lock, std::chrono::milliseconds(100), [&] { return done; })) {
                lock.unlock();
                options.progress(renderer.progress());
                lock.lock();
            }
        }
        worker.join();
        if (error) std::rethrow_exception(error);
        options.progress(renderer.progress());
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return renderer.result(seconds);
}

}  // namespace sweeptrace
