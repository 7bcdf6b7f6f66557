// Adaptive sampling is farm-safe: a render's nominal range [0, N) split into parts
// (RenderOptions::first_sample, render --samples A:B), each part rendering the pilot again for its
// weights, merges bit for bit to the single adaptive render, whatever the split (inside the
// pilot, at its end, past it, uneven) and the threads; the part file keeps each pixel's count;
// parts of an adaptive render do not merge with a uniform render's; and a --time budget stops at
// a pass boundary, the image being that of a --spp render of the passes it finished.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "cli_run.hpp"
#include "farm_test_identity.hpp"
#include "image_test_support.hpp"
#include "raytracer/accel/accel.hpp"
#include "raytracer/cli/render_part.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/image/partial_image.hpp"
#include "raytracer/render/adaptive_sampling.hpp"
#include "raytracer/render/renderer.hpp"
#include "raytracer/scene/load_scene.hpp"

namespace fs = std::filesystem;
using namespace sweeptrace;

namespace {

Scene adaptfarm_scene() {
    Scene s = load_scene(fs::path(SWEEPTRACE_SOURCE_DIR) / "scenes" / "cornell-box.json");
    s.film.width = 32;
    s.film.height = 24;
    return s;
}

RenderOptions adaptfarm_options(int begin, int end, int threads, AdaptiveError error) {
    RenderOptions o;
    o.first_sample = begin;
    o.spp = end - begin;
    o.seed = 3;
    o.max_depth = 5;
    o.adaptive = true;
    o.adaptive_error = error;
    o.threads = threads;
    return o;
}

}  // namespace

TEST_CASE("adaptive farm: any split into parts merges to the single adaptive render bit for bit", "[render][adaptive][farm]") {
    const Scene s = adaptfarm_scene();
    const std::unique_ptr<Accel> accel = make_accel(AccelKind::Bvh, s);
    const AdaptiveError error = GENERATE(AdaptiveError::Mse, AdaptiveError::Relative);
    constexpr int kSpp = 45;  // the pilot, then 29 nominal spp: three full passes of 8 and one of 5
    const RenderResult whole = render(s, *accel, adaptfarm_options(0, kSpp, 2, error));
    REQUIRE(whole.pixel_samples.size() == 32u * 24u);
    const auto [lo, hi] = std::minmax_element(whole.pixel_samples.begin(), whole.pixel_samples.end());
    REQUIRE(*lo < *hi);  // the allocation is uneven, so a wrong split would show

    const fs::path dir = fs::path(SWEEPTRACE_BINARY_DIR) / "adaptive-farm-tests" / "split";
    fs::remove_all(dir);
    fs::create_directories(dir);
    // Two parts at the pilot's end; three, the first inside the pilot and a cut off the passes'
    // grid; an uneven split of one-sample parts inside the pilot and one past it; parts at 1 and
    // 3 threads in turn. Each part goes through its file, so the file's counts are tested too.
    const std::vector<std::vector<int>> splits = {{0, 16, kSpp}, {0, 5, 29, kSpp}, {0, 1, 15, 16, 17, 40, kSpp}};
    for (const auto& cuts : splits) {
        std::vector<PartialImage> parts;
        std::vector<std::string> names;
        for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
            const RenderResult r = render(s, *accel, adaptfarm_options(cuts[i], cuts[i + 1], i % 2 == 0 ? 1 : 3, error));
            REQUIRE(r.stats.completed_spp == cuts[i + 1] - cuts[i]);
            const fs::path file = dir / ("part" + std::to_string(i) + ".exr");
            write_part(r, test::farm_test_identity(32, 24, 3, 5, "path", kSpp, error == AdaptiveError::Mse ? "on" : "relative"), cuts[i], file);
            parts.push_back(read_partial(file));
            names.push_back(file.string());
        }
        std::reverse(parts.begin(), parts.end());  // the merge orders them itself
        const PartialImage merged = merge_partials(parts, names);
        INFO("split into " << parts.size() << " parts, from " << cuts[1]);
        CHECK(merged.sums == whole.sums);
        CHECK(merged.counts == whole.pixel_samples);
        CHECK(testing::bitwise_equal(merged.mean(), whole.image));
    }
}

TEST_CASE("adaptive farm: a part of an adaptive render does not merge with a uniform render's", "[render][adaptive][farm][cli]") {
    const fs::path dir = fs::path(SWEEPTRACE_BINARY_DIR) / "adaptive-farm-tests" / "cli";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string base = "render '" + std::string(SWEEPTRACE_SOURCE_DIR) +
                             "/scenes/cornell-box.json' --width 24 --height 16 --spp 30 --quiet ";
    REQUIRE(test::run_sweeptrace(dir, base + "--adaptive on -o one.exr").exit_code == 0);
    REQUIRE(test::run_sweeptrace(dir, base + "--adaptive on --samples 0:20 -o a1.exr --threads 1").exit_code == 0);
    REQUIRE(test::run_sweeptrace(dir, base + "--adaptive on --samples 20:30 -o a2.exr --threads 3").exit_code == 0);
    REQUIRE(test::run_sweeptrace(dir, base + "--samples 0:20 -o u1.exr").exit_code == 0);
    REQUIRE(test::run_sweeptrace(dir, base + "--adaptive relative --samples 0:20 -o r1.exr").exit_code == 0);
    // The farm's promise, as a user checks it: the merged file is the single render's, byte for byte.
    const auto merged = test::run_sweeptrace(dir, "merge --quiet a2.exr a1.exr -o merged.exr");
    INFO(merged.err);
    REQUIRE(merged.exit_code == 0);
    CHECK(testing::bitwise_equal(read_image(dir / "merged.exr"), read_image(dir / "one.exr")));
    for (const auto& [first, message] : {std::pair<std::string, std::string>{"u1.exr", "adaptive sampling 'off' vs 'on'"},
                                         {"r1.exr", "adaptive sampling 'relative' vs 'on'"}}) {
        const auto r = test::run_sweeptrace(dir, "merge " + first + " a2.exr -o bad.exr");
        INFO(r.err);
        CHECK(r.exit_code == 2);
        CHECK(r.err.rfind("sweeptrace: error: ", 0) == 0);
        CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
        CHECK(r.err.find(message) != std::string::npos);
    }
    CHECK_FALSE(fs::exists(dir / "bad.exr"));
    // --skip-existing keeps a verified adaptive part, and not for a uniform render of the range.
    const std::string loud = base.substr(0, base.find("--quiet"));
    const auto kept = test::run_sweeptrace(dir, loud + "--adaptive on --samples 0:20 -o a1.exr --skip-existing");
    CHECK(kept.err.find("already a verified part of this render, kept") != std::string::npos);
    const auto redone = test::run_sweeptrace(dir, loud + "--samples 0:20 -o a1.exr --skip-existing");
    CHECK(redone.exit_code == 0);
    CHECK(redone.err.find("kept") == std::string::npos);
}

TEST_CASE("adaptive farm: a --time budget stops at a pass boundary, the image a --spp render's", "[render][adaptive]") {
    const Scene s = adaptfarm_scene();
    const std::unique_ptr<Accel> accel = make_accel(AccelKind::Bvh, s);
    RenderOptions timed = adaptfarm_options(0, 1 << 20, 2, AdaptiveError::Mse);
    timed.time_budget = 0.25;  // wall: somewhere in the passes, wherever the machine's load puts it
    const RenderResult t = render(s, *accel, timed);
    INFO("stopped at " << t.stats.completed_spp << " nominal spp");
    REQUIRE(t.stats.budget_spent);
    // A pass boundary: inside the pilot any pass; after it, the pilot plus whole passes of 8.
    CHECK((t.stats.completed_spp <= kAdaptivePilotSpp || (t.stats.completed_spp - kAdaptivePilotSpp) % kAdaptiveRoundSpp == 0));
    const RenderResult same = render(s, *accel, adaptfarm_options(0, t.stats.completed_spp, 1, AdaptiveError::Mse));
    CHECK(testing::bitwise_equal(t.image, same.image));
    CHECK(testing::bitwise_equal(t.variance, same.variance));
    CHECK(t.pixel_samples == same.pixel_samples);
    CHECK(t.stats.samples == same.stats.samples);
}
