// Path guiding: the directional quadtree's density integrates to 1 and is the one its sampling
// draws with (exact sum and chi-square), the BSDF + guide mixture's weights are f cos / (the
// density it sampled with), and guided renders are unbiased (they agree with unguided ones by the
// block z-test) and the same bit for bit at any thread count.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <set>
#include <vector>

#include <glm/geometric.hpp>

#include "convergence_harness.hpp"
#include "raytracer/image/diff.hpp"
#include "raytracer/render/guiding/guiding_quadtree.hpp"
#include "raytracer/render/guiding/guiding_sampler.hpp"
#include "raytracer/render/guiding/guiding_sd_tree.hpp"
#include "raytracer/render/sampling/random.hpp"
#include "raytracer/render/renderer.hpp"
#include "raytracer/render/sampling/sampling.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "render_test_scenes.hpp"
#include "render_test_stats.hpp"

using namespace sweeptrace;
using sweeptrace::test::DoublePrecisionAccel;
using sweeptrace::test::z_bound;
using sweeptrace::testing::same_bits;

namespace {

constexpr int kDepth = 7;  // the test tree's deepest leaves are 2^-7 wide on the square

// A lobe around `axis` (cosine power) on top of a uniform floor: a distribution with detail.
glm::vec3 lobe_direction(Rng& rng, const glm::vec3& axis) {
    if (rng.uniform() < 0.2f) return uniform_sphere(rng.uniform(), rng.uniform());
    const float cos_t = std::pow(rng.uniform(), 1.0f / 41.0f), phi = 2.0f * kPi * rng.uniform();
    const float sin_t = std::sqrt(std::max(0.0f, 1.0f - cos_t * cos_t));
    return Frame(axis).to_world({sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t});
}

// A trained tree: records, refined structure, records again (four iterations, as in rendering).
DirectionalQuadtree trained_tree() {
    const glm::vec3 axis = glm::normalize(glm::vec3(0.3f, -0.5f, 0.8f));
    Rng rng(5, 0, 0);
    DirectionalQuadtree tree;
    for (int iteration = 0; iteration < 4; ++iteration) {
        if (iteration > 0) tree = tree.refined(0.01, kDepth);
        for (int i = 0; i < 30000; ++i) tree.record(lobe_direction(rng, axis), 0.5f + rng.uniform());
    }
    tree.freeze();
    return tree;
}

// The probability of each cell of an n x n grid of the square, from pdf() at the centres of the
// finest cells (the density is constant on each of them, so the sum is exact up to rounding).
std::vector<double> cell_probabilities(const DirectionalQuadtree& tree, int n) {
    const int fine = 1 << kDepth, per = fine / n;
    std::vector<double> p(static_cast<std::size_t>(n) * n, 0.0);
    for (int j = 0; j < fine; ++j)
        for (int i = 0; i < fine; ++i) {
            const glm::vec2 centre((i + 0.5f) / fine, (j + 0.5f) / fine);
            const double d = tree.pdf(square_to_direction(centre)) * 4.0 * M_PI / (double(fine) * fine);
            p[static_cast<std::size_t>(j / per) * n + i / per] += d;
        }
    return p;
}

Scene smallpt(int width, int height) {
    Scene s = load_scene(std::filesystem::path(SWEEPTRACE_SOURCE_DIR) / "scenes" / "smallpt.json");
    s.film.width = width;
    s.film.height = height;
    return s;
}

// Guiding on, with the spp, depth and seed a test needs.
RenderOptions guided_options(int spp, int max_depth, std::uint64_t seed) {
    RenderOptions o;
    o.spp = spp;
    o.max_depth = max_depth;
    o.seed = seed;
    o.guiding = true;
    return o;
}

}  // namespace

TEST_CASE("guiding: the equal-area map round-trips and the quadtree's density integrates to 1", "[render][guiding]") {
    Rng rng(1, 2, 3);
    for (int i = 0; i < 1000; ++i) {
        const glm::vec3 d = uniform_sphere(rng.uniform(), rng.uniform());
        CHECK(glm::length(square_to_direction(direction_to_square(d)) - d) < 1e-5f);
    }
    const DirectionalQuadtree tree = trained_tree();
    CHECK(tree.depth() >= 5);  // the lobe really refined the tree
    CHECK(tree.node_count() > 20);
    double sum = 0.0;
    for (const double p : cell_probabilities(tree, 1 << kDepth)) sum += p;
    CHECK(sum == Approx(1.0).epsilon(1e-5));
}

TEST_CASE("guiding: the quadtree samples the density pdf() states (chi-square on a 32x32 grid)", "[render][guiding]") {
    const DirectionalQuadtree tree = trained_tree();
    constexpr int kGrid = 32;
    constexpr int kSamples = 400000;
    const std::vector<double> p = cell_probabilities(tree, kGrid);
    std::vector<int> count(p.size(), 0);
    Rng rng(9, 9, 9);
    double mc_integral = 0.0;  // E[1 / pdf] over samples = the measure of the support = 4 pi
    int density_differs = 0;   // the descent's density is pdf()'s but where the map's rounding changes cell
    for (int s = 0; s < kSamples; ++s) {
        float descent = 0.0f;
        const glm::vec3 d = tree.sample(rng.uniform(), rng.uniform(), &descent);
        if (descent != Approx(tree.pdf(d)).epsilon(1e-5)) ++density_differs;
        const glm::vec2 q = direction_to_square(d);
        ++count[static_cast<std::size_t>(int(q.y * kGrid)) * kGrid + int(q.x * kGrid)];
        mc_integral += 1.0 / tree.pdf(d);
    }
    double chi2 = 0.0;
    int dof = -1, impossible = 0;
    for (std::size_t c = 0; c < p.size(); ++c) {
        const double expected = p[c] * kSamples;
        if (expected <= 0.0) {
            impossible += count[c];
            continue;
        }
        chi2 += (count[c] - expected) * (count[c] - expected) / expected;
        ++dof;
    }
    INFO("chi2 " << chi2 << " on " << dof << " degrees of freedom");
    CHECK(impossible == 0);
    CHECK(chi2 < dof + 6.0 * std::sqrt(2.0 * dof));  // about 6 sigma of the chi-square distribution
    CHECK(mc_integral / kSamples == Approx(4.0 * M_PI).epsilon(0.02));
    INFO(density_differs << " samples of " << kSamples << " whose descent density differs from pdf()");
    CHECK(density_differs < kSamples / 1000);
}

TEST_CASE("guiding: mixture samples weigh f cos / (the mixture's density): E[weight] = albedo", "[render][guiding]") {
    const DirectionalQuadtree tree = trained_tree();
    Material m = test::diffuse(glm::vec3(0.6f));
    const glm::vec3 n = glm::normalize(glm::vec3(0.2f, 0.3f, 0.9f));
    ShadingContext ctx{Frame(n), n, glm::vec3(0.0f), true};
    ctx.wo_local = ctx.frame.to_local(glm::normalize(glm::vec3(0.5f, 0.1f, 0.7f)));
    Rng rng(4, 4, 4);
    test::Estimate weight, guided_share;
    for (int s = 0; s < 200000; ++s) {
        const float us = rng.uniform(), u0 = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
        BsdfSample bs;
        float bsdf_pdf = 0.0f;
        const bool ok = sample_guided(m, ctx, tree, us, u0, u1, u2, bs, bsdf_pdf);
        weight.add(ok ? bs.weight.g : 0.0);
        guided_share.add(us >= kBsdfFraction && ok ? 1.0 : 0.0);
        if (ok) {
            const BsdfEval e = eval_bsdf(m, ctx, bs.wi);
            CHECK(bs.pdf == Approx(guided_pdf(tree, e.pdf, bs.wi)));
            CHECK(bsdf_pdf == Approx(e.pdf));
        }
    }
    INFO("mean weight " << weight.mean << " +- " << weight.standard_error());
    CHECK(std::abs(weight.mean - 0.6) < z_bound(1) * weight.standard_error());
    CHECK(guided_share.mean > 0.1);  // the guide's samples took part (some fall below the surface)
}

TEST_CASE("guiding: every spatial leaf is reached, deep below the lookup grid, and outside points find the nearest", "[render][guiding]") {
    // 60000 records crowded into a cube of side 1/1024 in a corner of the unit box split the tree
    // some 30 levels deep there, below the 15 levels the lookup grid covers.
    GuidingSdTree sd;
    std::vector<GuideRecord> records;
    Rng rng(3, 3, 3);
    const float side = 1.0f / 1024.0f;
    for (int i = 0; i < 60000; ++i)
        records.push_back({glm::vec3(rng.uniform(), rng.uniform(), rng.uniform()) * side, glm::vec3(0.0f, 0.0f, 1.0f), 1.0f});
    records.push_back({glm::vec3(1.0f), glm::vec3(0.0f, 0.0f, 1.0f), 1.0f});  // the far corner of the box
    sd.add({records});
    sd.end_pass(1);
    REQUIRE(sd.leaf_count() >= 8);
    std::set<std::uint32_t> reached;
    for (int i = 0; i < 200000; ++i) {
        const glm::vec3 u(rng.uniform(), rng.uniform(), rng.uniform());
        const glm::vec3 p = i % 2 ? u * (2.0f * side) : u;
        reached.insert(sd.leaf_of(p));
        if (i % 10 == 0) CHECK(sd.leaf_of(p) == sd.leaf_of_from_root(p));  // the grid only shortens the descent
    }
    CHECK(reached.size() == sd.leaf_count());
    for (std::uint32_t leaf : reached) CHECK(leaf < sd.leaf_count());
    // Outside the box, and NaN, a point belongs to the leaf nearest along each axis.
    for (int i = 0; i < 1000; ++i) {
        const glm::vec3 p = glm::vec3(rng.uniform(), rng.uniform(), rng.uniform()) * side;
        CHECK(sd.leaf_of(glm::vec3(-100.0f, p.y, p.z)) == sd.leaf_of(glm::vec3(0.0f, p.y, p.z)));
        CHECK(sd.leaf_of(glm::vec3(p.x, -1e30f, p.z)) == sd.leaf_of(glm::vec3(p.x, 0.0f, p.z)));
        CHECK(sd.leaf_of(glm::vec3(p.x, p.y, NAN)) == sd.leaf_of(glm::vec3(p.x, p.y, -1.0f)));
    }
    CHECK(sd.leaf_of(glm::vec3(1e30f)) == sd.leaf_of(glm::vec3(1.0f)));
}

TEST_CASE("guiding: the spatial tree learns only between passes and splits where records crowd", "[render][guiding]") {
    GuidingSdTree sd;
    CHECK(sd.guide(glm::vec3(0.0f)) == nullptr);
    std::vector<GuideRecord> records;
    Rng rng(2, 2, 2);
    for (int i = 0; i < 60000; ++i)
        records.push_back({glm::vec3(rng.uniform(), rng.uniform(), rng.uniform()), glm::vec3(0.0f, 0.0f, 1.0f), 1.0f});
    sd.add({records});
    CHECK(sd.guide(glm::vec3(0.5f)) == nullptr);  // nothing learned until the iteration ends
    sd.end_pass(1);                                // iteration 0 (1 pass) ends
    CHECK(sd.iterations_done() == 1);
    CHECK(sd.leaf_count() >= 4);                   // 60000 records > 12000: split to <= 12000 each
    const DirectionalQuadtree* g = sd.guide(glm::vec3(0.5f));
    REQUIRE(g != nullptr);
    // Learned: everything came from +z, so its quadrant (a quarter of the sphere) has it all.
    CHECK(g->pdf(glm::vec3(0.0f, 0.0f, 1.0f)) == Approx(4.0 / (4.0 * M_PI)));
    sd.end_pass(2);                                     // mid iteration 1: nothing changes
    CHECK(sd.iterations_done() == 1);
}

TEST_CASE("guiding: a guided render is the same bit for bit on 1, 2 and 3 threads", "[render][guiding]") {
    // smallpt: next event estimation misses there, so the leaves guide (not so in scenes whose
    // light NEE finds, where guided and unguided renders are the same).
    const Scene s = smallpt(24, 16);
    const DoublePrecisionAccel accel(s);
    RenderOptions o;
    o.spp = 8;  // iterations of 1, 2 and 4 passes: the guide is rebuilt twice and used
    o.seed = 11;
    o.guiding = true;
    o.threads = 1;
    const RenderResult one = render(s, accel, o);
    o.threads = 2;
    const RenderResult two = render(s, accel, o);
    o.threads = 3;
    const RenderResult three = render(s, accel, o);
    CHECK(same_bits(one.image, two.image));
    CHECK(same_bits(one.image, three.image));
    o.guiding = false;
    CHECK_FALSE(same_bits(one.image, render(s, accel, o).image));  // guiding changed the paths
    const Scene lit = test::two_light_scene(24, 16);  // NEE finds both lights: nothing is guided
    const DoublePrecisionAccel lit_accel(lit);
    const RenderResult plain = render(lit, lit_accel, o);
    o.guiding = true;
    CHECK(same_bits(plain.image, render(lit, lit_accel, o).image));
}

TEST_CASE("guiding: guided and unguided renders of smallpt agree within the variance bound", "[render][guiding]") {
    const Scene scene = smallpt(32, 24);
    const DoublePrecisionAccel accel(scene);
    RenderOptions o = guided_options(128, 6, 31);
    const RenderResult guided = render(scene, accel, o);
    o.guiding = false;
    o.seed = 32;
    const RenderResult plain = render(scene, accel, o);
    Image variance(scene.film.width, scene.film.height);
    for (std::size_t i = 0; i < variance.pixels.size(); ++i)
        variance.pixels[i] = guided.variance.pixels[i] + plain.variance.pixels[i];
    BlockTestOptions options;
    options.block = 4;
    options.golden_is_8bit = false;
    const BlockTestResult t = block_test(plain.image, guided.image, variance, options);
    INFO(t.summary());
    CHECK(t.pass());
}

TEST_CASE("guiding: iterations double in paths, whole passes on a large image", "[render][guiding]") {
    GuidingSdTree small;
    small.set_paths_per_pass(128 * 96);  // up to kIterationPaths pixels: 2^k passes, as PPG
    for (int k = 0; k < GuidingSdTree::kTrainingIterations; ++k) CHECK(small.passes_of_iteration(k) == (1ll << k));
    GuidingSdTree large;
    large.set_paths_per_pass(1024 * 768);  // 2^k * 16384 paths, rounded up to passes of 786432
    const long long expected[] = {1, 1, 1, 1, 1, 1, 2, 3};
    for (int k = 0; k < GuidingSdTree::kTrainingIterations; ++k) CHECK(large.passes_of_iteration(k) == expected[k]);
    // end_pass follows it: iteration 6 takes passes 7 and 8 (a record a pass, from no light
    // sample, keeps guiding on).
    const std::vector<GuideRecord> record{{glm::vec3(0.5f), glm::vec3(0.0f, 0.0f, 1.0f), 1.0f}};
    for (int pass = 1; pass <= 7; ++pass) {
        large.add({record});
        large.end_pass(pass);
    }
    CHECK(large.iterations_done() == 6);
    large.add({record});
    large.end_pass(8);
    CHECK(large.iterations_done() == 7);
    CHECK(large.active());
}

TEST_CASE("guiding: switches itself off where next event estimation finds the light", "[render][guiding]") {
    // Each pass: vertex records everywhere, and light samples that find the light (lit) or not.
    const auto train = [](bool lit) {
        GuidingSdTree sd;
        Rng rng(3, 3, 3);
        int passes = 0;
        while (sd.training() && passes < 40) {
            std::vector<GuideRecord> records;
            for (int i = 0; i < 3000; ++i) {
                const glm::vec3 p(rng.uniform(), rng.uniform(), rng.uniform());
                records.push_back({p, glm::vec3(0.0f, 0.0f, 1.0f), 1.0f});
                records.push_back({p, glm::vec3(0.0f, 1.0f, 0.0f), lit ? 1.0f : 0.0f, 0, true});
            }
            for (GuideRecord& r : records) r.leaf = sd.leaf_of(r.point);
            sd.add({records});
            sd.end_pass(++passes);
        }
        return std::make_pair(sd.active(), passes);
    };
    const auto [lit_active, lit_passes] = train(true);
    CHECK_FALSE(lit_active);
    // Decided at the end of iteration kDecisionIteration (2^(k+1) - 1 passes), training stopped there.
    CHECK(lit_passes == (2 << GuidingSdTree::kDecisionIteration) - 1);
    const auto [dark_active, dark_passes] = train(false);
    CHECK(dark_active);
    CHECK(dark_passes == 40);
}

TEST_CASE("guiding: a large image's shorter iterations are the same bit for bit on 1 and 2 threads", "[render][guiding]") {
    // 256x192 = 49152 pixels: iterations of 1, 1, 2, 3 passes, so 5 passes rebuild the guide
    // three times (after passes 1, 2 and 4) and use it.
    const Scene s = smallpt(256, 192);
    const DoublePrecisionAccel accel(s);
    RenderOptions o = guided_options(5, 4, 13);
    o.threads = 1;
    const RenderResult one = render(s, accel, o);
    o.threads = 2;
    CHECK(same_bits(one.image, render(s, accel, o).image));
}
