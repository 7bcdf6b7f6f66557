#include "raytracer/cli/diff_pair.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "raytracer/image/alpha.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace {
namespace {

bool is_float_file(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext == ".exr" || ext == ".pfm";
}

// Noise test inputs must be linear floats: an 8-bit PNG's rounding and clamping at 1 are not
// noise, and its variance cannot be stored at all.
void require_float(const std::string& path, const char* role) {
    if (!is_float_file(path))
        throw InputError(std::string("the noise test needs linear float images: ") + role + " '" + path +
                         "' is not .exr or .pfm (8-bit PNG rounding and clipping are not noise)");
}

std::string over(const char* what, double value, double limit) {
    return std::string(what) + " " + number_text(value) + " > " + number_text(limit);
}

void compare_alpha(const PairInputs& in, PairReport& r, const DiffSettings& s, Image& a, Image& b) {
    const AlphaChannel alpha_a = read_alpha(in.a), alpha_b = read_alpha(in.b);
    r.alpha_present = alpha_a.present() || alpha_b.present();
    if (!r.alpha_present) return;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const float va = alpha_a.present() ? alpha_a.values[i] : 1.0f, vb = alpha_b.present() ? alpha_b.values[i] : 1.0f;
        r.alpha_max_difference = std::max(r.alpha_max_difference, static_cast<double>(std::abs(va - vb)));
    }
    a = composite_over(a, alpha_a, s.background);
    b = composite_over(b, alpha_b, s.background);
    if (r.alpha_max_difference > s.max_alpha) r.failures.push_back(over("alpha difference", r.alpha_max_difference, s.max_alpha));
}

void noise_test(const PairInputs& in, PairReport& r, const DiffSettings& s, const Image& a, const Image& b) {
    for (const auto& [path, role] : {std::pair{in.a, "A"}, {in.b, "B"}, {in.variance_a, "--variance-a"},
                                     {in.variance_b, "--variance-b"}})
        require_float(path, role);
    const Image va = read_image(in.variance_a), vb = read_image(in.variance_b);
    if (va.width != a.width || va.height != a.height || vb.width != a.width || vb.height != a.height)
        throw InputError("variance images must be " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                         " like the images");
    // The difference of two independent pixel means has the sum of their variances.
    Image sum = va;
    for (std::size_t i = 0; i < sum.pixels.size(); ++i) sum.pixels[i] += vb.pixels[i];
    BlockTestOptions o;
    o.block = s.block;
    o.golden_is_8bit = false;
    o.false_alarm = s.false_alarm;
    r.noise = block_test(b, a, sum, o);
    if (!r.noise->pass()) r.failures.push_back(over("noise test max z", r.noise->max_z, r.noise->z_limit));
}

void apply_limits(PairReport& r, const DiffSettings& s) {
    const DiffMetrics& m = r.metrics;
    const bool noise = r.noise.has_value();
    if (m.non_finite_a + m.non_finite_b > 0) r.failures.push_back("non-finite pixels");
    if (s.max_abs >= 0.0 && m.max_abs > s.max_abs) r.failures.push_back(over("max |a-b|", m.max_abs, s.max_abs));
    if (!noise && m.rmse > s.max_rmse) r.failures.push_back(over("RMSE", m.rmse, s.max_rmse));
    if (!noise && m.share_over > s.max_share)
        r.failures.push_back(over("share of pixels over the pixel threshold", m.share_over, s.max_share));
    if (s.max_delta_e >= 0.0 && m.mean_delta_e > s.max_delta_e)
        r.failures.push_back(over("mean delta E", m.mean_delta_e, s.max_delta_e));
    if (noise && !s.max_flip_given) return;  // noise alone moves FLIP: the z-test decides
    if (r.flip.mean > s.max_flip) r.failures.push_back(over("mean FLIP", r.flip.mean, s.max_flip));
    if (r.flip_local > s.max_local_flip)
        r.failures.push_back(over("local FLIP (worst 3x3 pixels)", r.flip_local, s.max_local_flip));
    if (r.failures.empty() && r.flip.mean > s.warn_flip) r.warnings.push_back(over("mean FLIP", r.flip.mean, s.warn_flip));
}

}  // namespace

std::string number_text(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char text[40];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

int PairReport::exit_code() const {
    if (!failures.empty()) return diff_exit_fail;
    return warnings.empty() ? diff_exit_pass : diff_exit_warn;
}

const char* PairReport::status() const {
    if (!failures.empty()) return "FAIL";
    return warnings.empty() ? "pass" : "WARN";
}

PairReport compare_pair(const PairInputs& in, const DiffSettings& s) {
    if (in.variance_a.empty() != in.variance_b.empty())
        throw InputError("the noise test needs both --variance-a and --variance-b");
    PairReport r;
    r.inputs = in;
    Image a = read_image(in.a), b = read_image(in.b);
    if (a.width != b.width || a.height != b.height)
        throw InputError("image sizes differ: '" + in.a + "' is " + std::to_string(a.width) + "x" +
                         std::to_string(a.height) + ", '" + in.b + "' is " + std::to_string(b.width) + "x" +
                         std::to_string(b.height));
    compare_alpha(in, r, s, a, b);
    r.metrics = compare_images(a, b, s.metric_options);
    FlipOptions fo = s.flip;
    fo.hdr = s.flip_mode == "hdr" || (s.flip_mode == "auto" && is_float_file(in.a) && is_float_file(in.b));
    r.flip = flip(b, a, fo);
    r.flip_local = flip_largest_window_mean(r.flip, 3);
    if (!in.variance_a.empty()) noise_test(in, r, s, a, b);
    apply_limits(r, s);
    return r;
}

void print_report(const PairReport& r, std::FILE* out) {
    const DiffMetrics& m = r.metrics;
    std::fprintf(out, "%s vs %s (reference): %dx%d\n", r.inputs.a.c_str(), r.inputs.b.c_str(), m.width, m.height);
    std::fprintf(out, "  RMSE                 %s\n", number_text(m.rmse).c_str());
    std::fprintf(out, "  PSNR                 %s dB (peak %s)\n", number_text(m.psnr).c_str(), number_text(m.psnr_peak).c_str());
    std::fprintf(out, "  mean |a-b|           %s\n", number_text(m.mean_abs).c_str());
    std::fprintf(out, "  max |a-b|            %s at (%d, %d)\n", number_text(m.max_abs).c_str(), m.max_x, m.max_y);
    std::fprintf(out, "  share over threshold %s\n", number_text(m.share_over).c_str());
    std::fprintf(out, "  mean delta E         %s (blurred CIELAB, not FLIP)\n", number_text(m.mean_delta_e).c_str());
    const FlipResult& f = r.flip;
    std::fprintf(out, "  %s mean       %s\n", f.exposures > 0 ? "HDR-FLIP" : "FLIP    ", number_text(f.mean).c_str());
    std::fprintf(out, "  FLIP weighted median %s, quartiles %s / %s, max %s at (%d, %d)\n",
                 number_text(f.weighted_median).c_str(), number_text(f.weighted_first_quartile).c_str(),
                 number_text(f.weighted_third_quartile).c_str(), number_text(f.max).c_str(), f.max_x, f.max_y);
    std::fprintf(out, "  FLIP worst 3x3 mean  %s\n", number_text(r.flip_local).c_str());
    if (f.exposures > 0)
        std::fprintf(out, "  HDR-FLIP exposures   %d from %s to %s stops\n", f.exposures,
                     number_text(f.start_exposure).c_str(), number_text(f.stop_exposure).c_str());
    if (r.alpha_present) std::fprintf(out, "  max alpha difference %s\n", number_text(r.alpha_max_difference).c_str());
    if (m.non_finite_a + m.non_finite_b > 0)
        std::fprintf(out, "  non-finite pixels    %zu in A, %zu in B\n", m.non_finite_a, m.non_finite_b);
    if (r.noise) std::fprintf(out, "  noise %s\n", r.noise->summary().c_str());
    if (r.failures.empty() && r.warnings.empty()) {
        std::fprintf(out, "within tolerance\n");
        return;
    }
    std::fprintf(out, r.failures.empty() ? "WARNING (within tolerance):" : "OVER tolerance:");
    for (const auto& o : r.failures.empty() ? r.warnings : r.failures) std::fprintf(out, " [%s]", o.c_str());
    std::fprintf(out, "\n");
}

}  // namespace sweeptrace
