#include "raytracer/image/feature_sums.hpp"

#include <cstddef>

namespace sweeptrace {

namespace {

// The eight half sums in one order, for the loops below and the part's words.
template <class Sums>
auto half_sums(Sums& s) {
    return std::array{&s.color[0], &s.color[1], &s.albedo[0], &s.albedo[1],
                      &s.normal[0], &s.normal[1], &s.position[0], &s.position[1]};
}

glm::vec3 variance_of(const PixelSum& s, const SquareSum* q, std::int64_t n) {
    return glm::vec3(static_cast<float>(variance_of_mean(s.rgb[0], q[0], n)),
                     static_cast<float>(variance_of_mean(s.rgb[1], q[1], n)),
                     static_cast<float>(variance_of_mean(s.rgb[2], q[2], n)));
}

}  // namespace

FeatureSums& FeatureSums::operator+=(const FeatureSums& o) {
    const auto mine = half_sums(*this);
    const auto theirs = half_sums(o);
    for (std::size_t k = 0; k < mine.size(); ++k) *mine[k] += *theirs[k];
    for (int h = 0; h < 2; ++h) count[h] += o.count[h];
    for (int k = 0; k < kSquares; ++k) square[k] += o.square[k];
    return *this;
}

void add_feature_sample(FeatureSums& sums, std::int64_t sample, const glm::vec3& color, const SampleFeatures& f,
                        bool& clamped) {
    const int h = static_cast<int>(sample & 1);
    ++sums.count[h];
    clamped = false;
    const glm::vec3* values[4] = {&color, &f.albedo, &f.normal, &f.position};
    PixelSum* halves[4] = {&sums.color[h], &sums.albedo[h], &sums.normal[h], &sums.position[h]};
    for (int v = 0; v < 4; ++v)
        for (int c = 0; c < 3; ++c) {
            bool k = false;
            const SumInt x = to_fixed((*values[v])[c], k);
            clamped = clamped || k;
            halves[v]->rgb[c] += x;
            // Squares: colour, albedo, normal whole; of the position only z, the depth.
            if (v < 3) add_square(sums.square[3 * v + c], x);
            else if (c == 2) add_square(sums.square[9], x);
        }
}

FeatureLayers feature_layers(const std::vector<FeatureSums>& sums, int width, int height) {
    FeatureLayers L;
    L.width = width;
    L.height = height;
    for (Image* im : {&L.color, &L.color_variance, &L.albedo, &L.albedo_variance, &L.normal, &L.normal_variance, &L.position})
        *im = Image(width, height);
    for (int h = 0; h < 2; ++h)
        for (Image* im : {&L.half_color[h], &L.half_albedo[h], &L.half_normal[h], &L.half_position[h]})
            *im = Image(width, height);
    L.depth_variance.assign(static_cast<std::size_t>(width) * height, 0.0f);
    for (std::size_t i = 0; i < sums.size(); ++i) {
        const FeatureSums& s = sums[i];
        const std::int64_t n = static_cast<std::int64_t>(s.count[0]) + s.count[1];
        PixelSum whole[4];
        const PixelSum* evens[4] = {&s.color[0], &s.albedo[0], &s.normal[0], &s.position[0]};
        const PixelSum* odds[4] = {&s.color[1], &s.albedo[1], &s.normal[1], &s.position[1]};
        Image* means[4] = {&L.color, &L.albedo, &L.normal, &L.position};
        std::array<Image, 2>* halves[4] = {&L.half_color, &L.half_albedo, &L.half_normal, &L.half_position};
        for (int v = 0; v < 4; ++v) {
            whole[v] = *evens[v];
            whole[v] += *odds[v];
            means[v]->pixels[i] = mean_of(whole[v], n);
            (*halves[v])[0].pixels[i] = mean_of(*evens[v], s.count[0]);
            (*halves[v])[1].pixels[i] = mean_of(*odds[v], s.count[1]);
        }
        L.color_variance.pixels[i] = variance_of(whole[0], &s.square[0], n);
        L.albedo_variance.pixels[i] = variance_of(whole[1], &s.square[3], n);
        L.normal_variance.pixels[i] = variance_of(whole[2], &s.square[6], n);
        L.depth_variance[i] = static_cast<float>(variance_of_mean(whole[3].rgb[2], s.square[9], n));
    }
    return L;
}

const std::vector<std::string>& feature_word_names() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> v;
        const char* sums[8] = {"colorEven", "colorOdd", "albedoEven", "albedoOdd",
                               "normalEven", "normalOdd", "positionEven", "positionOdd"};
        for (const char* s : sums)
            for (int c = 0; c < 3; ++c)
                for (int k = 0; k < 4; ++k) v.push_back(std::string("aov.") + s + "." + std::to_string(c) + "." + std::to_string(k));
        v.push_back("aov.countEven");
        v.push_back("aov.countOdd");
        for (int q = 0; q < FeatureSums::kSquares; ++q)
            for (int k = 0; k < 8; ++k) v.push_back("aov.square." + std::to_string(q) + "." + std::to_string(k));
        return v;
    }();
    return names;
}

// Words in feature_word_names() order; each 128-bit sum least significant word first, each
// 256-bit square likewise.
void feature_to_words(const FeatureSums& s, std::uint32_t* w) {
    for (const PixelSum* p : half_sums(s))
        for (int c = 0; c < 3; ++c) {
            const auto u = static_cast<SumUInt>(p->rgb[c]);
            for (int k = 0; k < 4; ++k) *w++ = static_cast<std::uint32_t>(u >> (32 * k));
        }
    for (int h = 0; h < 2; ++h) *w++ = static_cast<std::uint32_t>(s.count[h]);
    for (const SquareSum& q : s.square)
        for (int l = 0; l < 4; ++l) {
            *w++ = static_cast<std::uint32_t>(q.limb[l]);
            *w++ = static_cast<std::uint32_t>(q.limb[l] >> 32);
        }
}

FeatureSums feature_from_words(const std::uint32_t* w) {
    FeatureSums s;
    for (PixelSum* p : half_sums(s))
        for (int c = 0; c < 3; ++c) {
            SumUInt u = 0;
            for (int k = 0; k < 4; ++k) u |= static_cast<SumUInt>(*w++) << (32 * k);
            p->rgb[c] = static_cast<SumInt>(u);
        }
    for (int h = 0; h < 2; ++h) s.count[h] = static_cast<std::int32_t>(*w++);
    for (SquareSum& q : s.square)
        for (int l = 0; l < 4; ++l) {
            const std::uint64_t lo = *w++;
            q.limb[l] = lo | (static_cast<std::uint64_t>(*w++) << 32);
        }
    return s;
}

}  // namespace sweeptrace
