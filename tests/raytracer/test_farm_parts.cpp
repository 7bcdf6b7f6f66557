// Farm parts in the library: sample ranges rendered separately and merged are the single render
// bit for bit (any split, any thread count), the fixed-point sum is exact where it says it is,
// the part file keeps every bit and rejects damage, and the merge refuses other renders,
// overlaps and gaps with messages that name them.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "raytracer/image/partial_image.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/render/renderer.hpp"
#include "farm_test_identity.hpp"
#include "render_test_scenes.hpp"

namespace fs = std::filesystem;
using namespace sweeptrace;

namespace {

constexpr int kSpp = 12;

RenderIdentity identity() { return test::farm_test_identity(37, 21, 42, 8, "vcm", kSpp); }

PartialImage render_part(const Scene& s, const Accel& accel, int begin, int end, int threads) {
    RenderOptions o;
    o.spp = end - begin;
    o.first_sample = begin;
    o.seed = 42;
    o.threads = threads;
    const RenderResult r = render(s, accel, o);
    PartialImage p;
    p.id = identity();
    p.sample_begin = begin;
    p.sample_end = end;
    p.sums = r.sums;
    return p;
}

bool same_bits(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec3)) == 0;
}

PartialImage part(int begin, int end) {
    PartialImage p;
    p.id = identity();
    p.sample_begin = begin;
    p.sample_end = end;
    p.sums.assign(static_cast<std::size_t>(p.id.width) * p.id.height, PixelSum{});
    return p;
}

std::string merge_error(const std::vector<PartialImage>& parts, const std::vector<std::string>& names) {
    try {
        merge_partials(parts, names);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST_CASE("farm: any split into sample ranges merges to the single render bit for bit", "[farm]") {
    const Scene s = test::two_light_scene(37, 21);
    const test::DoublePrecisionAccel accel(s);
    RenderOptions o;
    o.spp = kSpp;
    o.seed = 42;
    o.threads = 2;
    const RenderResult whole = render(s, accel, o);

    // Even, uneven, single-sample parts, and every part a sample of its own.
    const std::vector<std::vector<int>> splits = {
        {0, 12}, {0, 6, 12}, {0, 5, 6, 12}, {0, 1, 2, 3, 10, 11, 12}, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}};
    for (const auto& cuts : splits) {
        std::vector<PartialImage> parts;
        std::vector<std::string> names;
        for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
            parts.push_back(render_part(s, accel, cuts[i], cuts[i + 1], 1 + static_cast<int>(i % 3)));
            names.push_back("part" + std::to_string(i));
        }
        std::reverse(parts.begin(), parts.end());  // the merge orders them itself
        const PartialImage merged = merge_partials(parts, names);
        INFO("split into " << parts.size() << " parts");
        CHECK(merged.sums == whole.sums);
        CHECK(same_bits(merged.mean(), whole.image));
    }
}

TEST_CASE("farm: double sums depend on the split, the fixed-point sum is exact down to 2^-33", "[farm]") {
    // Why the renderer does not sum in double: four float samples of one pixel, summed in a
    // running sum (one machine) and as two parts of two samples each. 1 + 2^-24 lies halfway
    // between two floats; the running sum drops each 2^-53 (a tie, to even), the split keeps their
    // sum 2^-52, and the float means differ. Rare with real samples, but possible.
    const float samples[4] = {1.0f, 0x1p-24f, 0x1p-53f, 0x1p-53f};
    double running = 0.0;
    for (float v : samples) running += v;
    const double split = (double(samples[0]) + samples[1]) + (double(samples[2]) + samples[3]);
    CHECK(static_cast<float>(running / 4) != static_cast<float>(split / 4));
    // In fixed point both orders give the same integer and so the same mean, the correctly
    // rounded one; these floats are added exactly.
    bool clamped = true;
    PixelSum one, first, second;
    for (int i = 0; i < 4; ++i) {
        add_sample(one, glm::vec3(samples[i]), clamped);
        add_sample(i < 2 ? first : second, glm::vec3(samples[i]), clamped);
        CHECK_FALSE(clamped);
    }
    first += second;
    CHECK(first == one);
    CHECK(mean_of(one, 4).x == static_cast<float>(split / 4));
    CHECK(static_cast<double>(to_fixed(0x1p-33f, clamped)) * 0x1p-56 == 0x1p-33);
    CHECK(static_cast<double>(to_fixed(3.0f + 0x1p-22f, clamped)) * 0x1p-56 == double(3.0f + 0x1p-22f));
    // Below 2^-33 a float is rounded to the grid: half a step at most.
    CHECK(to_fixed(0x1.4p-56f, clamped) == 1);  // 1.25 steps
    CHECK(to_fixed(0x1.8p-56f, clamped) == 2);  // 1.5 steps: the tie goes to even
    // The clamp is at 2^40 and is reported.
    CHECK(to_fixed(0x1p41f, clamped) == to_fixed(0x1p40f, clamped));
    CHECK(clamped);
    PixelSum s;
    add_sample(s, glm::vec3(1.0f, -2.0f, 0x1p50f), clamped);
    CHECK(clamped);
    CHECK(mean_of(s, 1) == glm::vec3(1.0f, -2.0f, 0x1p40f));
}

TEST_CASE("farm: to_fixed rounds every float as nearbyint does, without calling it", "[farm]") {
    // to_fixed rounds by adding and subtracting 1.5 * 2^52 below 2^51 and takes larger values as
    // they are: the integer must be nearbyint's (ties to even) for every float, so sums made
    // before the change and after agree. Each binary exponent from the subnormals to the clamp,
    // both signs, its extreme mantissas and the ties between grid steps, and random mantissas.
    std::mt19937 rng(7);
    std::uniform_int_distribution<std::uint32_t> mantissa(0, (1u << 23) - 1);
    std::int64_t checked = 0, mismatched = 0;
    auto check = [&](std::uint32_t bits) {
        float v;
        std::memcpy(&v, &bits, sizeof v);
        if (!std::isfinite(v) || std::fabs(v) > kSampleLimit) return;
        bool clamped = true;
        const SumInt got = to_fixed(v, clamped);
        const SumInt want = static_cast<SumInt>(std::nearbyint(static_cast<double>(v) * 0x1p56));
        ++checked;
        mismatched += got != want || clamped ? 1 : 0;
    };
    for (std::uint32_t sign = 0; sign < 2; ++sign)
        for (std::uint32_t exponent = 0; exponent <= 127 + 40; ++exponent) {
            const std::uint32_t high = sign << 31 | exponent << 23;
            for (std::uint32_t m : {0u, 1u, 2u, 3u, (1u << 22) - 1, 1u << 22, (1u << 22) + 1, (1u << 23) - 2, (1u << 23) - 1})
                check(high | m);
            for (int k = 0; k < 2048; ++k) check(high | mantissa(rng));
        }
    CHECK(checked > 600000);
    CHECK(mismatched == 0);
}

TEST_CASE("farm: a part file keeps every bit of its sums and its identity, and rejects damage", "[farm]") {
    const fs::path dir = fs::path(SWEEPTRACE_BINARY_DIR) / "farm-tests" / "part-file";
    fs::remove_all(dir);
    fs::create_directories(dir);
    PartialImage p = part(3, 7);
    p.id.seed = 0xfedcba9876543210ull;  // above 2^63: the attribute keeps all 64 bits
    for (std::size_t i = 0; i < p.sums.size(); ++i) {
        const SumInt big = (static_cast<SumInt>(1) << 126) - static_cast<SumInt>(i);  // all four words in use
        p.sums[i].rgb[0] = big;
        p.sums[i].rgb[1] = -big;
        p.sums[i].rgb[2] = static_cast<SumInt>(i) << 56;
    }
    write_partial(p, dir / "p.exr");
    const PartialImage back = read_partial(dir / "p.exr");
    CHECK(back.id == p.id);
    CHECK(back.sample_begin == 3);
    CHECK(back.sample_end == 7);
    CHECK(back.sums == p.sums);

    // One byte changed in the middle of the file: the EXR decoder or the checksum must notice.
    std::string bytes;
    {
        std::ifstream in(dir / "p.exr", std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x10);
    std::ofstream(dir / "damaged.exr", std::ios::binary) << bytes;
    CHECK_THROWS_AS(read_partial(dir / "damaged.exr"), InputError);
    // A plain image is not a part.
    write_image(p.mean(), dir / "plain.exr");
    CHECK_THROWS_WITH(read_partial(dir / "plain.exr"), Catch::Contains("not a sweeptrace part"));

    // A part of format 4 (before the sampler was recorded; its header's version string patched
    // back, the header being uncompressed) is refused by its version, saying what to do.
    const std::string key = std::string("sweeptrace.part") + '\0' + "string" + '\0';
    std::string old_format;
    {
        std::ifstream in(dir / "p.exr", std::ios::binary);
        old_format.assign(std::istreambuf_iterator<char>(in), {});
    }
    const std::size_t at = old_format.find(key);
    REQUIRE(at != std::string::npos);
    REQUIRE(old_format[at + key.size() + 4] == '5');  // after the 4-byte length
    old_format[at + key.size() + 4] = '4';
    std::ofstream(dir / "format4.exr", std::ios::binary) << old_format;
    CHECK_THROWS_WITH(read_partial_header(dir / "format4.exr"),
                      Catch::Contains("part format 4, this program reads 5 (render the part again with this program)"));

    // An adaptive part keeps each pixel's count, and its mean is over that count.
    PartialImage a = part(3, 7);
    a.id.adaptive = "relative";
    a.counts.assign(a.sums.size(), 0);
    for (std::size_t i = 0; i < a.sums.size(); ++i) {
        a.counts[i] = static_cast<int>(i % 5);  // 0: a pixel this short range gave no sample
        a.sums[i].rgb[0] = static_cast<SumInt>(3 * a.counts[i]) << kSumFractionBits;
    }
    write_partial(a, dir / "a.exr");
    const PartialImage a_back = read_partial(dir / "a.exr");
    CHECK(a_back.id == a.id);
    CHECK(a_back.counts == a.counts);
    CHECK(a_back.sums == a.sums);
    CHECK(a_back.mean().pixels[4].x == 3.0f);
    CHECK(a_back.mean().pixels[5].x == 0.0f);
    a.counts.clear();  // an adaptive part must say its counts
    CHECK_THROWS_WITH(write_partial(a, dir / "b.exr"), Catch::Contains("needs a count per pixel"));
}

TEST_CASE("farm: the merge names a different render, an overlap and a gap", "[farm]") {
    PartialImage adaptive = part(4, 12);
    adaptive.id.adaptive = "on";
    CHECK(merge_error({part(0, 4), adaptive}, {"a.exr", "b.exr"}) ==
          "'b.exr' is not a part of the same render as 'a.exr': adaptive sampling 'off' vs 'on'");
    PartialImage other = part(4, 12);
    other.id.max_depth = 5;
    CHECK(merge_error({part(0, 4), other}, {"a.exr", "b.exr"}) ==
          "'b.exr' is not a part of the same render as 'a.exr': max depth 8 vs 5");
    other = part(4, 12);
    other.id.accel = "embree";
    CHECK(merge_error({part(0, 4), other}, {"a.exr", "b.exr"}) ==
          "'b.exr' is not a part of the same render as 'a.exr': accel 'bvh' vs 'embree'");
    other = part(4, 12);
    other.id.integrator = "bdpt";
    CHECK(merge_error({part(0, 4), other}, {"a.exr", "b.exr"}) ==
          "'b.exr' is not a part of the same render as 'a.exr': integrator 'vcm' vs 'bdpt'");
    // A sample index draws other numbers under another sampler: such parts are another image.
    other = part(4, 12);
    other.id.sampler = "independent";
    CHECK(merge_error({part(0, 4), other}, {"a.exr", "b.exr"}) ==
          "'b.exr' is not a part of the same render as 'a.exr': sampler 'sobol' vs 'independent'");
    other = part(4, 12);
    other.id.scene_hash = "ffffffffffffffff";
    CHECK_THAT(merge_error({part(0, 4), other}, {"a.exr", "b.exr"}), Catch::Contains("scene hash"));

    CHECK(merge_error({part(0, 5), part(4, 12)}, {"a.exr", "b.exr"}) ==
          "parts 'a.exr' [0, 5) and 'b.exr' [4, 12) overlap on samples [4, 5)");
    CHECK(merge_error({part(4, 12), part(0, 4), part(0, 4)}, {"a.exr", "b.exr", "c.exr"}) ==
          "parts 'b.exr' [0, 4) and 'c.exr' [0, 4) overlap on samples [0, 4)");
    CHECK(merge_error({part(1, 12)}, {"a.exr"}) == "samples [0, 1) of the 12-sample render are missing: no part covers them");
    CHECK(merge_error({part(0, 3), part(5, 12)}, {"a.exr", "b.exr"}) ==
          "samples [3, 5) of the 12-sample render are missing: no part covers them");
    CHECK(merge_error({part(0, 3), part(3, 11)}, {"a.exr", "b.exr"}) ==
          "samples [11, 12) of the 12-sample render are missing: no part covers them");
    CHECK(merge_error({}, {}) == "merge: no parts given");
    CHECK(merge_error({part(0, 3), part(3, 12)}, {"a.exr", "b.exr"}) == "(no error)");
}
