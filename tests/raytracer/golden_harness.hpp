#pragma once
// The image tests' comparison of a render against its golden (reference_images/), and what a
// failing comparison leaves behind: build/image-tests/<label>/{golden,actual,heatmap,diff}.png,
// actual.pfm, report.html, and build/image-tests/report.html listing every failing label.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "raytracer/accel/accel.hpp"
#include "raytracer/image/diff.hpp"
#include "raytracer/render/planted_defect.hpp"
#include "raytracer/render/renderer.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace::testing {

// One line of reference_images/goldens.txt.
struct GoldenSpec {
    std::string scene;
    int width = 0, height = 0, max_depth = 0;
    int golden_spp = 0;
    std::uint64_t golden_seed = 0;
    int test_spp = 0;
    int block = 8;
};

std::vector<GoldenSpec> read_golden_specs();
const GoldenSpec& golden_spec(const std::string& scene);

// reference_images/<scene>.png, and <scene>-variance.exr: the golden render's per-sample variance
// per pixel and channel (linear, float), the noise a correct render must show.
std::filesystem::path golden_image_path(const GoldenSpec& spec);
std::filesystem::path golden_variance_path(const GoldenSpec& spec);

// Renders the golden (BVH, golden_spp, golden_seed) and writes both files. Only
// tools/make-goldens.sh calls this (through a hidden test case); tests never do.
void make_golden(const GoldenSpec& spec);

// scenes/<scene>.json with the film size and depth of the spec.
Scene load_golden_scene(const GoldenSpec& spec);

// Renders `scene` as the image tests do (spec's test_spp and depth, all threads).
RenderResult render_for_test(const Scene& scene, AccelKind accel, const GoldenSpec& spec, std::uint64_t seed,
                             PlantedDefect defect = PlantedDefect::None);

struct GoldenVerdict {
    BlockTestResult block;
    DiffMetrics metrics;  // plain metrics in display space, for the report
    bool accepted() const { return block.pass(); }
};

// The criterion: block_test of the render (with its per-pixel variance) against the 8-bit golden,
// the golden's own noise counted by spp_test / spp_golden. When the verdict differs from
// `expect_accept` (the test is about to fail), writes the artefacts under `label` and prints
// their paths; SWEEPTRACE_KEEP_IMAGES=1 in the environment writes them always.
GoldenVerdict compare_to_golden(const GoldenSpec& spec, const RenderResult& render, const std::string& label,
                                bool expect_accept);

}  // namespace sweeptrace::testing
