#include "raytracer/image/feature_sums.hpp"

#include <emmintrin.h>

#include <cstddef>

#include <glm/gtc/type_ptr.hpp>

namespace sweeptrace {

namespace {

// The four 128-bit half sums and the four 64-bit ones in one order, for the loops below and the
// part's words.
template <class Sums>
auto wide_sums(Sums& s) {
    return std::array{&s.color[0], &s.color[1], &s.position[0], &s.position[1]};
}
template <class Sums>
auto bounded_sums(Sums& s) {
    return std::array{&s.albedo[0], &s.albedo[1], &s.normal[0], &s.normal[1]};
}

// Feature values on the 2^-32 grid, two at a time (SSE2, x86-64's baseline): clamped to
// [-limit, limit] by minpd and maxpd (the sums' widths rely on it; NaN, which no integrator
// records, goes to the limit: minpd returns its second operand when either is NaN), scaled by
// 2^32 (exact), and rounded to the nearest integer, ties to even, by adding 1.5 * 2^52: for
// |r| < 2^51 the sum lies in [2^52, 2^53), where doubles are the integers, so its bits less those
// of 1.5 * 2^52 are round(r) as an int64 (nearest_int64's first case, without its branch and
// without a conversion instruction, which SSE2 lacks for 64-bit integers). |r| <= 2^32 for the
// bounded features; the position takes this path when all its coordinates are below 2^19.
__m128i fixed_pair(__m128d v, __m128d limit) {
    const __m128d magic = _mm_set1_pd(0x1.8p52);
    const __m128d c = _mm_max_pd(_mm_min_pd(v, limit), _mm_sub_pd(_mm_setzero_pd(), limit));
    const __m128d r = _mm_add_pd(_mm_mul_pd(c, _mm_set1_pd(0x1p32)), magic);
    return _mm_sub_epi64(_mm_castpd_si128(r), _mm_castpd_si128(magic));
}
// A position coordinate as the general case: clamped as above, then nearest_int64 (|r| < 2^62).
std::int64_t position_fixed(float v) {
    const float below = v < kFeaturePositionLimit ? v : kFeaturePositionLimit;
    const float c = below > -kFeaturePositionLimit ? below : -kFeaturePositionLimit;
    return nearest_int64(static_cast<double>(c) * 0x1p32);
}

// x^2 of a bounded feature's |x| <= 2^32: up to 2^64, one 64 x 64 -> 128-bit product.
SumUInt bounded_square(std::int64_t x) { return static_cast<SumUInt>(static_cast<SumInt>(x) * x); }

// |x| of an int64 (as unsigned, so that INT64_MIN's is right too).
std::uint64_t magnitude64(std::int64_t x) {
    return x < 0 ? std::uint64_t{0} - static_cast<std::uint64_t>(x) : static_cast<std::uint64_t>(x);
}

// The lanes of a pair of int64 (SSE2: the low one moves to a register directly, the high one after
// an unpack).
std::int64_t low_lane(__m128i v) { return _mm_cvtsi128_si64(v); }
std::int64_t high_lane(__m128i v) { return _mm_cvtsi128_si64(_mm_unpackhi_epi64(v, v)); }

// The mean of `n` samples whose sums on the 2^-32 grid are s[3]: as mean_of (partial_sum.hpp),
// one rounding to double, an exact scale, a division and the cast to float.
template <class Int>
glm::vec3 feature_mean(const Int (&s)[3], std::int64_t n) {
    if (n <= 0) return glm::vec3(0.0f);
    glm::dvec3 v;
    for (int c = 0; c < 3; ++c) v[c] = static_cast<double>(s[c]) * 0x1p-32;
    return glm::vec3(v / static_cast<double>(n));
}

}  // namespace

static_assert(kFeatureFractionBits == 32, "fixed_pair, position_fixed and feature_mean scale by 2^32 literally");

FeatureSums& FeatureSums::operator+=(const FeatureSums& o) {
    const auto mine = wide_sums(*this);
    const auto theirs = wide_sums(o);
    for (std::size_t k = 0; k < mine.size(); ++k) *mine[k] += *theirs[k];
    const auto my_bounded = bounded_sums(*this);
    const auto their_bounded = bounded_sums(o);
    for (std::size_t k = 0; k < my_bounded.size(); ++k)
        for (int c = 0; c < 3; ++c) my_bounded[k]->v[c] += their_bounded[k]->v[c];
    for (int h = 0; h < 2; ++h) count[h] += o.count[h];
    for (int c = 0; c < 3; ++c) color_square[c] += o.color_square[c];
    depth_square += o.depth_square;
    for (int k = 0; k < 6; ++k) bounded_square[k] += o.bounded_square[k];
    return *this;
}

namespace {

// Whether to_fixed of all three colour channels is their float times 2^56 truncated, exactly: each
// magnitude is 0 or in [2^-33, 2^7), where the float is a multiple of 2^-56 (so the product is
// an integer) below 2^63.
bool plain_color(const float* color) {
    const __m128 v = _mm_setr_ps(color[0], color[1], color[2], 0.0f);
    const __m128 m = _mm_andnot_ps(_mm_set1_ps(-0.0f), v);
    const __m128 in_range = _mm_and_ps(_mm_cmpge_ps(m, _mm_set1_ps(0x1p-33f)), _mm_cmplt_ps(m, _mm_set1_ps(0x1p7f)));
    return _mm_movemask_ps(_mm_or_ps(in_range, _mm_cmpeq_ps(m, _mm_setzero_ps()))) == 0xf;
}

// A sample's values in fixed point, as the sums take them: the colour on the 2^-56 grid when
// plain_color (else left unset: the caller takes to_fixed), the features on the 2^-32 grid.
struct FixedSample {
    std::int64_t color[3];
    std::int64_t bounded[6];  // albedo R, G, B, normal X, Y, Z
    std::int64_t position[3];
};

// The conversions, SSE2 pairs; true when the colour was plain. Each lane goes to the struct as one
// int64 (movq), and is read back as that int64: storing 16-byte pairs and reading other pairs,
// as this code did once, stalled on store-to-load forwarding (a 16-byte load across two stores),
// the largest single cost of add_feature_sample in its profile.
[[gnu::always_inline]] inline bool fixed_sample(const FeatureSample& fs, FixedSample& v) {
    const float* color = glm::value_ptr(fs.color);
    // Nearly every sample: to_fixed without its cases, a value below 2^63.
    const bool plain = plain_color(color);
    if (plain)
        for (int c = 0; c < 3; ++c) v.color[c] = static_cast<std::int64_t>(static_cast<double>(color[c]) * 0x1p56);
    // Albedo then normal, six floats in a row (SampleFeatures), as three pairs of doubles:
    // (a.x, a.y), (a.z, n.x), (n.y, n.z).
    static_assert(offsetof(SampleFeatures, normal) == offsetof(SampleFeatures, albedo) + 3 * sizeof(float));
    const float* bounded = glm::value_ptr(fs.features.albedo);
    const __m128 lo = _mm_loadu_ps(bounded), hi = _mm_loadu_ps(bounded + 2);  // a.xyz n.x; a.z n.xyz
    const __m128d unit = _mm_set1_pd(1.0);
    const __m128i pairs[3] = {fixed_pair(_mm_cvtps_pd(lo), unit), fixed_pair(_mm_cvtps_pd(_mm_movehl_ps(lo, lo)), unit),
                              fixed_pair(_mm_cvtps_pd(_mm_movehl_ps(hi, hi)), unit)};
    for (int k = 0; k < 3; ++k) {
        v.bounded[2 * k] = low_lane(pairs[k]);
        v.bounded[2 * k + 1] = high_lane(pairs[k]);
    }
    // Position: below 2^19 scene units (nearly every hit) the pairs' path, else one by one.
    const float* position = glm::value_ptr(fs.features.position);
    const __m128 pos = _mm_setr_ps(position[0], position[1], position[2], 0.0f);
    const __m128 magnitude = _mm_andnot_ps(_mm_set1_ps(-0.0f), pos);
    if (_mm_movemask_ps(_mm_cmplt_ps(magnitude, _mm_set1_ps(0x1p19f))) == 0xf) {
        const __m128d limit = _mm_set1_pd(static_cast<double>(kFeaturePositionLimit));
        const __m128i xy = fixed_pair(_mm_cvtps_pd(pos), limit);
        v.position[0] = low_lane(xy);
        v.position[1] = high_lane(xy);
        v.position[2] = low_lane(fixed_pair(_mm_cvtps_pd(_mm_movehl_ps(pos, pos)), limit));
    } else {
        for (int c = 0; c < 3; ++c) v.position[c] = position_fixed(position[c]);
    }
    return plain;
}

}  // namespace

void add_feature_sample(FeatureSums& s, std::int64_t sample, const FeatureSample& fs) {
    // Straight into `s`, channel by channel (a whole FeatureSums in locals measured slower: the
    // locals spill). (add_small_square's carry branch measured faster than a branch-free chain of
    // _addcarry_u64 through memory on this machine's AMD EPYC: 16-19 against 33-37 ns a sample,
    // in a loop of 64 samples a pixel.)
    const int h = static_cast<int>(sample & 1);
    ++s.count[h];
    FixedSample v;
    if (fixed_sample(fs, v)) {
        for (int c = 0; c < 3; ++c) {
            s.color[h].rgb[c] += v.color[c];
            add_small_square(s.color_square[c], magnitude64(v.color[c]));
        }
    } else {
        for (int c = 0; c < 3; ++c) {
            bool clamped = false;  // counted where the same value joins the pixel's colour sum
            const SumInt x = to_fixed(fs.color[c], clamped);
            s.color[h].rgb[c] += x;
            add_square(s.color_square[c], x);
        }
    }
    for (int c = 0; c < 3; ++c) {
        s.albedo[h].v[c] += v.bounded[c];
        s.normal[h].v[c] += v.bounded[3 + c];
    }
    for (int k = 0; k < 6; ++k) s.bounded_square[k] += bounded_square(v.bounded[k]);
    for (int c = 0; c < 3; ++c) s.position[h].rgb[c] += v.position[c];
    add_small_square(s.depth_square, magnitude64(v.position[2]));  // below 2^62
}

void add_feature_samples(FeatureSums& s, std::int64_t first, const FeatureSample* samples, int n) {
    // A full batch of plain colours (nearly every pixel's): each channel's four values summed in
    // registers, two to each half, and their squares (each below 2^126 for the colour and the
    // depth, 2^64 for the bounded features, so four fit 128 bits), then one addition to each sum.
    // Anything else: sample by sample.
    static_assert(kFeatureBatch == 4, "the halves below take samples 0 and 2, 1 and 3");
    FixedSample v[kFeatureBatch];
    bool plain = n == kFeatureBatch;
    for (int k = 0; k < n && plain; ++k) plain = fixed_sample(samples[k], v[k]);
    if (!plain) {
        for (int k = 0; k < n; ++k) add_feature_sample(s, first + k, samples[k]);
        return;
    }
    const int a = static_cast<int>(first & 1), b = 1 - a;  // the halves of samples 0 and 2, 1 and 3
    s.count[0] += 2;
    s.count[1] += 2;
    for (int c = 0; c < 3; ++c) {
        s.color[a].rgb[c] += static_cast<SumInt>(v[0].color[c]) + v[2].color[c];
        s.color[b].rgb[c] += static_cast<SumInt>(v[1].color[c]) + v[3].color[c];
        SumUInt q = 0;
        for (const FixedSample& x : v) q += static_cast<SumUInt>(magnitude64(x.color[c])) * magnitude64(x.color[c]);
        add_narrow(s.color_square[c], q);
    }
    for (int k = 0; k < 6; ++k) {
        BoundedSum* halves = k < 3 ? s.albedo : s.normal;
        halves[a].v[k % 3] += v[0].bounded[k] + v[2].bounded[k];
        halves[b].v[k % 3] += v[1].bounded[k] + v[3].bounded[k];
        SumUInt q = 0;
        for (const FixedSample& x : v) q += bounded_square(x.bounded[k]);
        s.bounded_square[k] += q;
    }
    for (int c = 0; c < 3; ++c) {
        s.position[a].rgb[c] += static_cast<SumInt>(v[0].position[c]) + v[2].position[c];
        s.position[b].rgb[c] += static_cast<SumInt>(v[1].position[c]) + v[3].position[c];
    }
    SumUInt q = 0;
    for (const FixedSample& x : v) q += static_cast<SumUInt>(magnitude64(x.position[2])) * magnitude64(x.position[2]);
    add_narrow(s.depth_square, q);
}

FeatureLayers feature_layers(const std::vector<FeatureSums>& sums, int width, int height) {
    FeatureLayers L;
    fill_feature_layers(sums.data(), width, height, L);
    return L;
}

void fill_feature_layers(const FeatureSums* sums, int width, int rows, FeatureLayers& L) {
    const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(rows);
    if (L.width != width || L.height != rows) {
        L.width = width;
        L.height = rows;
        for (Image* im : {&L.color, &L.color_variance, &L.albedo, &L.albedo_variance, &L.normal, &L.normal_variance, &L.position})
            *im = Image(width, rows);
        for (int h = 0; h < 2; ++h)
            for (Image* im : {&L.half_color[h], &L.half_albedo[h], &L.half_normal[h], &L.half_position[h]})
                *im = Image(width, rows);
        L.depth_variance.assign(pixels, 0.0f);
    }
    constexpr int F = kFeatureFractionBits;
    for (std::size_t i = 0; i < pixels; ++i) {
        const FeatureSums& s = sums[i];
        const std::int64_t n[2] = {s.count[0], s.count[1]};
        const std::int64_t all = n[0] + n[1];
        PixelSum color = s.color[0], position = s.position[0];
        color += s.color[1];
        position += s.position[1];
        BoundedSum albedo = s.albedo[0], normal = s.normal[0];
        for (int c = 0; c < 3; ++c) {
            albedo.v[c] += s.albedo[1].v[c];
            normal.v[c] += s.normal[1].v[c];
        }
        L.color.pixels[i] = mean_of(color, all);
        L.albedo.pixels[i] = feature_mean(albedo.v, all);
        L.normal.pixels[i] = feature_mean(normal.v, all);
        L.position.pixels[i] = feature_mean(position.rgb, all);
        for (int h = 0; h < 2; ++h) {
            L.half_color[h].pixels[i] = mean_of(s.color[h], n[h]);
            L.half_albedo[h].pixels[i] = feature_mean(s.albedo[h].v, n[h]);
            L.half_normal[h].pixels[i] = feature_mean(s.normal[h].v, n[h]);
            L.half_position[h].pixels[i] = feature_mean(s.position[h].rgb, n[h]);
        }
        for (int c = 0; c < 3; ++c) {
            L.color_variance.pixels[i][c] = static_cast<float>(variance_of_mean(color.rgb[c], s.color_square[c], all));
            L.albedo_variance.pixels[i][c] = static_cast<float>(variance_of_mean(albedo.v[c], s.bounded_square[c], all, F));
            L.normal_variance.pixels[i][c] = static_cast<float>(variance_of_mean(normal.v[c], s.bounded_square[3 + c], all, F));
        }
        L.depth_variance[i] = static_cast<float>(variance_of_mean(position.rgb[2], s.depth_square, all, F));
    }
}

const std::vector<std::string>& feature_word_names() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> v;
        auto add = [&v](const std::string& name, int channels, int words) {
            for (int c = 0; c < channels; ++c)
                for (int k = 0; k < words; ++k) {
                    std::string n = "aov." + name;
                    if (channels > 1) n.append(".").append(std::to_string(c));
                    v.push_back(n.append(".").append(std::to_string(k)));
                }
        };
        for (const char* s : {"colorEven", "colorOdd", "positionEven", "positionOdd"}) add(s, 3, 4);
        for (const char* s : {"albedoEven", "albedoOdd", "normalEven", "normalOdd"}) add(s, 3, 2);
        v.push_back("aov.countEven");
        v.push_back("aov.countOdd");
        add("colorSquare", 3, 8);
        add("depthSquare", 1, 8);
        add("albedoSquare", 3, 4);
        add("normalSquare", 3, 4);
        return v;
    }();
    return names;
}

namespace {

// An unsigned integer of `words` 32-bit words, least significant first.
void put_words(SumUInt u, int words, std::uint32_t*& w) {
    for (int k = 0; k < words; ++k) *w++ = static_cast<std::uint32_t>(u >> (32 * k));
}
SumUInt get_words(int words, const std::uint32_t*& w) {
    SumUInt u = 0;
    for (int k = 0; k < words; ++k) u |= static_cast<SumUInt>(*w++) << (32 * k);
    return u;
}

}  // namespace

// Words in feature_word_names() order; each sum two's complement, least significant word first.
void feature_to_words(const FeatureSums& s, std::uint32_t* w) {
    for (const PixelSum* p : wide_sums(s))
        for (int c = 0; c < 3; ++c) put_words(static_cast<SumUInt>(p->rgb[c]), 4, w);
    for (const BoundedSum* p : bounded_sums(s))
        for (int c = 0; c < 3; ++c) put_words(static_cast<std::uint64_t>(p->v[c]), 2, w);
    for (int h = 0; h < 2; ++h) *w++ = static_cast<std::uint32_t>(s.count[h]);
    for (const SquareSum* q : {&s.color_square[0], &s.color_square[1], &s.color_square[2], &s.depth_square})
        for (int l = 0; l < 4; ++l) put_words(q->limb[l], 2, w);
    for (const SumUInt q : s.bounded_square) put_words(q, 4, w);
}

FeatureSums feature_from_words(const std::uint32_t* w) {
    FeatureSums s;
    for (PixelSum* p : wide_sums(s))
        for (int c = 0; c < 3; ++c) p->rgb[c] = static_cast<SumInt>(get_words(4, w));
    for (BoundedSum* p : bounded_sums(s))
        for (int c = 0; c < 3; ++c) p->v[c] = static_cast<std::int64_t>(static_cast<std::uint64_t>(get_words(2, w)));
    for (int h = 0; h < 2; ++h) s.count[h] = static_cast<std::int32_t>(*w++);
    for (SquareSum* q : {&s.color_square[0], &s.color_square[1], &s.color_square[2], &s.depth_square})
        for (int l = 0; l < 4; ++l) q->limb[l] = static_cast<std::uint64_t>(get_words(2, w));
    for (SumUInt& q : s.bounded_square) q = get_words(4, w);
    return s;
}

}  // namespace sweeptrace
