#include "raytracer/scene/pbrt_spectra.hpp"

#include <cmath>
#include <utility>

#include <glm/common.hpp>

#include "raytracer/scene/named_metals.hpp"

namespace sweeptrace::pbrt {

namespace {

double lobe(double x, double mu, double s1, double s2) {
    const double t = (x - mu) / (x < mu ? s1 : s2);
    return std::exp(-0.5 * t * t);
}

// Wyman, Sloan, Shirley (2013), "Simple Analytic Approximations to the CIE XYZ Color Matching
// Functions", the multi-lobe fit (their equation 2); wavelength in nm.
glm::dvec3 cie_xyz(double nm) {
    const double x = 1.056 * lobe(nm, 599.8, 37.9, 31.0) + 0.362 * lobe(nm, 442.0, 16.0, 26.7) -
                     0.065 * lobe(nm, 501.1, 20.4, 26.2);
    const double y = 0.821 * lobe(nm, 568.8, 46.9, 40.5) + 0.286 * lobe(nm, 530.9, 16.3, 31.1);
    const double z = 1.217 * lobe(nm, 437.0, 11.8, 36.0) + 0.681 * lobe(nm, 459.0, 26.0, 13.8);
    return {x, y, z};
}

glm::dvec3 xyz_to_linear_srgb(const glm::dvec3& c) {
    return {3.2404542 * c.x - 1.5371385 * c.y - 0.4985314 * c.z, -0.9692660 * c.x + 1.8760108 * c.y + 0.0415560 * c.z,
            0.0556434 * c.x - 0.2040259 * c.y + 1.0572252 * c.z};
}

}  // namespace

glm::dvec3 blackbody_rgb(double kelvin) {
    if (!(kelvin > 0.0)) return glm::dvec3(0.0);
    constexpr double h = 6.62606957e-34, c = 299792458.0, kb = 1.3806488e-23;
    glm::dvec3 xyz(0.0);
    for (double nm = 360.0; nm <= 830.0; nm += 5.0) {
        const double l = nm * 1e-9;
        const double planck = (2.0 * h * c * c) / (std::pow(l, 5.0) * (std::exp((h * c) / (l * kb * kelvin)) - 1.0));
        xyz += planck * cie_xyz(nm);
    }
    if (!(xyz.y > 0.0) || !std::isfinite(xyz.y)) return glm::dvec3(0.0);
    const glm::dvec3 rgb = xyz_to_linear_srgb(xyz / xyz.y);
    return glm::max(rgb, glm::dvec3(0.0));
}

glm::dvec3 sampled_rgb(const std::vector<double>& pairs) {
    auto at = [&](double nm) {
        const std::size_t n = pairs.size() / 2;
        if (n == 0) return 0.0;
        if (nm <= pairs[0]) return pairs[1];
        for (std::size_t i = 1; i < n; ++i) {
            const double l0 = pairs[2 * (i - 1)], l1 = pairs[2 * i];
            if (nm <= l1) {
                const double t = l1 > l0 ? (nm - l0) / (l1 - l0) : 1.0;
                return pairs[2 * (i - 1) + 1] * (1.0 - t) + pairs[2 * i + 1] * t;
            }
        }
        return pairs[2 * n - 1];
    };
    return {at(610.0), at(550.0), at(465.0)};
}

const std::vector<std::string>& known_metals() {
    static const std::vector<std::string> metals = [] {
        std::vector<std::string> names;
        for (const NamedMetal& m : named_metals()) names.emplace_back(m.name);
        return names;
    }();
    return metals;
}

std::string known_metal_spectra() {
    std::string list;
    for (const std::string& m : known_metals()) list += (list.empty() ? "" : ",") + m;
    return "metal-{" + list + "}-{eta,k}";
}

std::optional<std::string> named_metal(const std::string& spectrum, std::string& part) {
    for (const std::string& m : known_metals())
        for (const char* p : {"eta", "k"})
            if (spectrum == "metal-" + m + "-" + p) {
                part = p;
                return m;
            }
    return std::nullopt;
}

std::optional<double> named_glass_ior(const std::string& spectrum) {
    // Schott's catalogue n_d (587.56 nm) for the glasses pbrt-v4 names; its "glass-F5", "-F10" and
    // "-F11" hold the dense flints SF5, SF10 and SF11.
    static const std::pair<const char*, double> glasses[] = {
        {"glass-BK7", 1.51680}, {"glass-BAF10", 1.67003}, {"glass-FK51A", 1.48656}, {"glass-LASF9", 1.85025},
        {"glass-F5", 1.67270},  {"glass-F10", 1.72825},   {"glass-F11", 1.78472}};
    for (const auto& [name, n] : glasses)
        if (spectrum == name) return n;
    return std::nullopt;
}

}  // namespace sweeptrace::pbrt
