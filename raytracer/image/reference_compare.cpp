// The numbers of `sweeptrace reference-check`: see reference_compare.hpp for what each one means.
#include "raytracer/image/reference_compare.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "raytracer/image/srgb.hpp"

namespace sweeptrace {
namespace {

bool finite_rgb(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Per source pixel: the noise variance estimate r^2 k / (k - 1) (see the header), or -1 where the
// pixel is not finite or has no finite neighbour.
std::vector<glm::vec3> source_noise(const Image& src) {
    std::vector<glm::vec3> out(src.pixels.size(), glm::vec3(-1.0f));
    for (int y = 0; y < src.height; ++y)
        for (int x = 0; x < src.width; ++x) {
            if (!finite_rgb(src.at(x, y))) continue;
            glm::dvec3 sum(0.0);
            int k = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int u = x + dx, v = y + dy;
                    if (u < 0 || v < 0 || u >= src.width || v >= src.height || !finite_rgb(src.at(u, v))) continue;
                    sum += glm::dvec3(src.at(u, v));
                    ++k;
                }
            if (k < 2) continue;
            const glm::dvec3 r = glm::dvec3(src.at(x, y)) - sum / double(k);
            out[static_cast<std::size_t>(y) * src.width + x] = glm::vec3(r * r * (double(k) / (k - 1)));
        }
    return out;
}

double rgb_channel(const glm::dvec3& v, int c) { return c == 0 ? v.x : c == 1 ? v.y : v.z; }

}  // namespace

DownsampledReference downsample_reference(const Image& reference, int factor) {
    const int w = reference.width / factor, h = reference.height / factor;
    DownsampledReference out{Image(w, h), std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h, 1), Image(w, h)};
    const std::vector<glm::vec3> noise = source_noise(reference);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            glm::dvec3 sum(0.0), noise_sum(0.0);
            int n = 0, n_noise = 0;
            for (int sy = y * factor; sy < (y + 1) * factor; ++sy)
                for (int sx = x * factor; sx < (x + 1) * factor; ++sx) {
                    const glm::vec3& p = reference.at(sx, sy);
                    if (!finite_rgb(p)) continue;
                    sum += glm::dvec3(p);
                    ++n;
                    const glm::vec3& e = noise[static_cast<std::size_t>(sy) * reference.width + sx];
                    if (e.x >= 0.0f) noise_sum += glm::dvec3(e), ++n_noise;
                }
            const std::size_t i = static_cast<std::size_t>(y) * w + x;
            out.valid[i] = n == factor * factor;
            if (n > 0) out.image.pixels[i] = glm::vec3(sum / double(n));
            if (n > 0 && n_noise > 0) out.variance.pixels[i] = glm::vec3(noise_sum / double(n_noise) / double(n));
        }
    return out;
}

BlockComparison compare_blocks(const Image& ours, const Image& our_variance, const Image& reference,
                               const Image& reference_variance, const std::vector<std::uint8_t>& valid, int block,
                               double our_variance_scale) {
    BlockComparison r;
    r.block = block;
    r.blocks_x = (ours.width + block - 1) / block;
    r.blocks_y = (ours.height + block - 1) / block;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    r.z.assign(static_cast<std::size_t>(r.blocks_x) * r.blocks_y, nan);
    r.relative_error.assign(r.z.size(), nan);

    glm::dvec3 sum_ours(0.0), sum_ref(0.0);
    std::size_t n_valid = 0;
    std::size_t within3 = 0, within5 = 0;
    std::vector<double> errors;
    for (int by = 0; by < r.blocks_y; ++by)
        for (int bx = 0; bx < r.blocks_x; ++bx) {
            glm::dvec3 o(0.0), f(0.0), var(0.0);
            int n = 0;
            for (int y = by * block; y < std::min(ours.height, (by + 1) * block); ++y)
                for (int x = bx * block; x < std::min(ours.width, (bx + 1) * block); ++x) {
                    const std::size_t i = static_cast<std::size_t>(y) * ours.width + x;
                    if (!valid[i]) continue;
                    o += glm::dvec3(ours.pixels[i]);
                    f += glm::dvec3(reference.pixels[i]);
                    var += our_variance_scale * glm::dvec3(our_variance.pixels[i]) + glm::dvec3(reference_variance.pixels[i]);
                    ++n;
                }
            sum_ours += o;
            sum_ref += f;
            n_valid += n;
            if (2 * n < block * block) continue;
            double z = 0.0, worst = -1.0;
            for (int c = 0; c < 3; ++c) {
                const double d = rgb_channel(o, c) - rgb_channel(f, c), s = std::sqrt(rgb_channel(var, c));
                const double zc = d == 0.0 ? 0.0 : s > 0.0 ? d / s : std::copysign(std::numeric_limits<double>::infinity(), d);
                if (std::abs(zc) > worst) worst = std::abs(zc), z = zc;
            }
            const std::size_t b = static_cast<std::size_t>(by) * r.blocks_x + bx;
            r.z[b] = z;
            ++r.tested;
            within3 += worst < 3.0;
            within5 += worst < 5.0;
            const double ref_total = f.x + f.y + f.z;
            if (ref_total > 0.0) {
                r.relative_error[b] = (o.x + o.y + o.z - ref_total) / ref_total;
                errors.push_back(r.relative_error[b]);
            }
        }
    if (r.tested > 0) {
        r.share_within_3 = double(within3) / double(r.tested);
        r.share_within_5 = double(within5) / double(r.tested);
    }
    if (!errors.empty()) {
        std::sort(errors.begin(), errors.end());
        const std::size_t m = errors.size() / 2;
        r.median_relative_error = errors.size() % 2 ? errors[m] : 0.5 * (errors[m - 1] + errors[m]);
    }
    for (int c = 0; c < 3; ++c) {
        const double ref = rgb_channel(sum_ref, c);
        (c == 0 ? r.mean_ratio.x : c == 1 ? r.mean_ratio.y : r.mean_ratio.z) = ref > 0.0 ? rgb_channel(sum_ours, c) / ref : nan;
    }
    r.valid_share = ours.pixels.empty() ? 0.0 : double(n_valid) / double(ours.pixels.size());
    return r;
}

double block_variance_scale(const std::vector<Image>& batches, const Image& whole_variance,
                            const std::vector<std::uint8_t>& valid, int block) {
    const std::size_t k = batches.size();
    if (k < 2) return 1.0;
    const int w = whole_variance.width, h = whole_variance.height;
    double replicas = 0.0, pixels = 0.0;
    std::vector<glm::dvec3> sums(k);
    for (int by = 0; by * block < h; ++by)
        for (int bx = 0; bx * block < w; ++bx) {
            std::fill(sums.begin(), sums.end(), glm::dvec3(0.0));
            glm::dvec3 var(0.0);
            int n = 0;
            for (int y = by * block; y < std::min(h, (by + 1) * block); ++y)
                for (int x = bx * block; x < std::min(w, (bx + 1) * block); ++x) {
                    const std::size_t i = static_cast<std::size_t>(y) * w + x;
                    if (!valid[i]) continue;
                    for (std::size_t b = 0; b < k; ++b) sums[b] += glm::dvec3(batches[b].pixels[i]);
                    var += glm::dvec3(whole_variance.pixels[i]);
                    ++n;
                }
            if (2 * n < block * block) continue;  // the blocks compare_blocks tests
            glm::dvec3 mean(0.0);
            for (const glm::dvec3& v : sums) mean += v / double(k);
            glm::dvec3 spread(0.0);
            for (const glm::dvec3& v : sums) spread += (v - mean) * (v - mean);
            const glm::dvec3 of_mean = spread / double(k - 1) / double(k);  // of the block sum over the whole render
            replicas += of_mean.x + of_mean.y + of_mean.z;
            pixels += var.x + var.y + var.z;
        }
    return pixels > 0.0 ? replicas / pixels : 1.0;
}

Image comparison_picture(const Image& ours, const Image& reference, const std::vector<std::uint8_t>& valid,
                         const BlockComparison& blocks) {
    const int w = ours.width, h = ours.height;
    std::vector<float> brightest;
    for (std::size_t i = 0; i < reference.pixels.size(); ++i)
        if (valid[i]) {
            const glm::vec3& p = reference.pixels[i];
            brightest.push_back(std::max({p.x, p.y, p.z}));
        }
    float scale = 1.0f;
    if (!brightest.empty()) {
        const std::size_t k = std::min(brightest.size() - 1, brightest.size() * 99 / 100);
        std::nth_element(brightest.begin(), brightest.begin() + static_cast<std::ptrdiff_t>(k), brightest.end());
        if (brightest[k] > 0.0f) scale = 1.0f / brightest[k];
    }
    Image out(3 * w, h);
    const auto shown = [scale](const glm::vec3& p) {
        return finite_rgb(p) ? glm::clamp(p * scale, glm::vec3(0.0f), glm::vec3(1.0f)) : glm::vec3(1.0f, 0.0f, 1.0f);
    };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * w + x;
            out.at(x, y) = shown(ours.pixels[i]);
            out.at(w + x, y) = shown(reference.pixels[i]);
            const double z = blocks.z[static_cast<std::size_t>(y / blocks.block) * blocks.blocks_x + x / blocks.block];
            glm::vec3 c;
            if (!valid[i]) c = glm::vec3(0.5f);
            else if (std::isnan(z)) c = glm::vec3(0.1f);
            else {
                const float t = static_cast<float>(std::min(1.0, std::abs(z) / 5.0));
                c = z > 0.0 ? glm::vec3(t, 0.15f * t, 0.0f) : glm::vec3(0.0f, 0.3f * t, t);
            }
            // The colours are chosen as display values; write_image encodes linear values.
            out.at(2 * w + x, y) = {srgb_decode(c.x), srgb_decode(c.y), srgb_decode(c.z)};
        }
    return out;
}

}  // namespace sweeptrace
