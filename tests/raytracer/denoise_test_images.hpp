#pragma once
// Synthetic NFOR inputs with a known truth, for the denoiser's tests: a colour that is a known
// function of the features plus seeded Gaussian noise, independent in the even and odd halves,
// with the variance of the mean it was drawn with.
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "raytracer/denoise/feature_channels.hpp"
#include "raytracer/denoise/nfor.hpp"
#include "raytracer/image/exr_channels.hpp"

namespace sweeptrace::testing {

struct SyntheticImage {
    denoise::NforInput input;
    denoise::Planes truth;  // the colour without noise
};

// features(x, y, f) is feature f (of feature_channel_names()) at a pixel, noise-free;
// truth(x, y, c, features) the colour channel c there; `sigma` the standard deviation of one
// half's noise (the full mean's is sigma / sqrt 2).
inline SyntheticImage synthetic_image(int w, int h, std::uint64_t seed, float sigma, const std::function<float(int, int, int)>& features,
                                      const std::function<float(int, int, int, const float*)>& truth) {
    const int m = int(denoise::feature_channel_names().size());
    SyntheticImage s;
    auto blank = [&](int c) { return denoise::Buffers{{w, h, c}, {w, h, c}, {w, h, c}, {w, h, c}}; };
    s.input.color = blank(3);
    s.input.features = blank(m);
    s.truth = denoise::Planes(w, h, 3);
    std::mt19937_64 rng(seed);
    std::normal_distribution<float> noise(0.0f, sigma);
    std::vector<float> f(std::size_t(m), 0.0f);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            for (int i = 0; i < m; ++i) {
                f[std::size_t(i)] = features(x, y, i);
                for (denoise::Planes* p : {&s.input.features.mean, &s.input.features.even, &s.input.features.odd}) p->at(i, x, y) = f[std::size_t(i)];
            }
            for (int c = 0; c < 3; ++c) {
                const float t = truth(x, y, c, f.data());
                const float even = t + noise(rng), odd = t + noise(rng);
                s.truth.at(c, x, y) = t;
                s.input.color.even.at(c, x, y) = even;
                s.input.color.odd.at(c, x, y) = odd;
                s.input.color.mean.at(c, x, y) = 0.5f * (even + odd);
                s.input.color.variance.at(c, x, y) = 0.5f * sigma * sigma;
            }
        }
    return s;
}

// The same image as the channels of a feature EXR (feature_channels.hpp's names).
inline ExrChannels as_channels(const denoise::NforInput& in) {
    ExrChannels image;
    image.width = in.color.mean.width;
    image.height = in.color.mean.height;
    auto put = [&](const std::vector<std::string>& names, const denoise::Buffers& b) {
        for (std::size_t c = 0; c < names.size(); ++c) {
            const std::string& n = names[c];
            const std::string var = denoise::variance_channel_name(n);
            const std::size_t count = b.mean.pixels();
            image.channels[n].assign(b.mean.channel(int(c)), b.mean.channel(int(c)) + count);
            image.channels["Even." + n].assign(b.even.channel(int(c)), b.even.channel(int(c)) + count);
            image.channels["Odd." + n].assign(b.odd.channel(int(c)), b.odd.channel(int(c)) + count);
            image.channels[var].assign(b.variance.channel(int(c)), b.variance.channel(int(c)) + count);
        }
    };
    put(denoise::color_channel_names(), in.color);
    put(denoise::feature_channel_names(), in.features);
    return image;
}

// A textured, lit-looking test image: albedo a per-pixel random texture (a high-frequency
// pattern no spatial filter can recover from the noisy colour), normals of a tilted plane,
// depth growing across it; colour = 0.05 + 0.9 x albedo (a known first-order dependence).
inline SyntheticImage textured_image(int w, int h, std::uint64_t seed, float sigma) {
    std::mt19937_64 tex(seed ^ 0x9e3779b97f4a7c15ull);
    std::uniform_real_distribution<float> u(0.1f, 0.9f);
    std::vector<float> albedo(std::size_t(w) * std::size_t(h) * 3);
    for (float& a : albedo) a = u(tex);
    return synthetic_image(
        w, h, seed, sigma,
        [&](int x, int y, int f) {
            if (f < 3) return albedo[(std::size_t(y) * std::size_t(w) + std::size_t(x)) * 3 + std::size_t(f)];
            if (f < 6) return f == 4 ? 0.8f : f == 5 ? 0.6f : 0.0f;
            return 2.0f + 0.01f * float(x + y);
        },
        [](int, int, int c, const float* f) { return 0.05f + 0.9f * f[c]; });
}

}  // namespace sweeptrace::testing
