#include "raytracer/scene/pbrt/pbrt_spectra.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <system_error>
#include <utility>

#include <glm/common.hpp>

#include "raytracer/input_error.hpp"
#include "raytracer/scene/named_metals.hpp"

namespace sweeptrace::pbrt {

namespace {

double lobe(double x, double mu, double s1, double s2) {
    const double t = (x - mu) / (x < mu ? s1 : s2);
    return std::exp(-0.5 * t * t);
}

// A number of a spectrum file: what from_chars reads, a leading '+' allowed, finite.
bool spectrum_number(std::string_view s, double& out) {
    const char* b = s.data();
    const char* e = s.data() + s.size();
    if (b != e && *b == '+') ++b;
    const auto r = std::from_chars(b, e, out);
    return r.ec == std::errc() && r.ptr == e && std::isfinite(out);
}

std::string short_number(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", x);
    return buf;
}

std::string number_place(const std::vector<int>* lines, std::size_t i) {
    return lines ? "line " + std::to_string((*lines)[i]) + ": " : "";
}

}  // namespace

// Wyman, Sloan, Shirley (2013), "Simple Analytic Approximations to the CIE XYZ Color Matching
// Functions", the multi-lobe fit (their equation 2); wavelength in nm.
glm::dvec3 cie_xyz_1931(double nm) {
    const double x = 1.056 * lobe(nm, 599.8, 37.9, 31.0) + 0.362 * lobe(nm, 442.0, 16.0, 26.7) -
                     0.065 * lobe(nm, 501.1, 20.4, 26.2);
    const double y = 0.821 * lobe(nm, 568.8, 46.9, 40.5) + 0.286 * lobe(nm, 530.9, 16.3, 31.1);
    const double z = 1.217 * lobe(nm, 437.0, 11.8, 36.0) + 0.681 * lobe(nm, 459.0, 26.0, 13.8);
    return {x, y, z};
}

glm::dvec3 linear_srgb_from_xyz(const glm::dvec3& c) {
    return {3.2404542 * c.x - 1.5371385 * c.y - 0.4985314 * c.z, -0.9692660 * c.x + 1.8760108 * c.y + 0.0415560 * c.z,
            0.0556434 * c.x - 0.2040259 * c.y + 1.0572252 * c.z};
}

glm::dvec3 blackbody_rgb(double kelvin) {
    if (!(kelvin > 0.0)) return glm::dvec3(0.0);
    constexpr double h = 6.62606957e-34, c = 299792458.0, kb = 1.3806488e-23;
    glm::dvec3 xyz(0.0);
    for (double nm = 360.0; nm <= 830.0; nm += 5.0) {
        const double l = nm * 1e-9;
        const double planck = (2.0 * h * c * c) / (std::pow(l, 5.0) * (std::exp((h * c) / (l * kb * kelvin)) - 1.0));
        xyz += planck * cie_xyz_1931(nm);
    }
    if (!(xyz.y > 0.0) || !std::isfinite(xyz.y)) return glm::dvec3(0.0);
    const glm::dvec3 rgb = linear_srgb_from_xyz(xyz / xyz.y);
    return glm::max(rgb, glm::dvec3(0.0));
}

double sampled_at(const std::vector<double>& pairs, double nm) {
    const std::size_t n = pairs.size() / 2;
    if (n == 0) return 0.0;
    if (nm <= pairs[0]) return pairs[1];
    if (nm >= pairs[2 * (n - 1)]) return pairs[2 * n - 1];
    // The first pair at or past nm (binary search over the wavelengths, the even entries).
    std::size_t lo = 1, hi = n - 1;
    while (lo < hi) {
        const std::size_t mid = (lo + hi) / 2;
        if (pairs[2 * mid] < nm) lo = mid + 1;
        else hi = mid;
    }
    const double l0 = pairs[2 * (lo - 1)], l1 = pairs[2 * lo];
    const double t = l1 > l0 ? (nm - l0) / (l1 - l0) : 1.0;
    return pairs[2 * (lo - 1) + 1] * (1.0 - t) + pairs[2 * lo + 1] * t;
}

glm::dvec3 sampled_rgb(const std::vector<double>& pairs) {
    return {sampled_at(pairs, 610.0), sampled_at(pairs, 550.0), sampled_at(pairs, 465.0)};
}

std::string check_spectrum_pairs(const std::vector<double>& pairs, const std::vector<int>* lines) {
    if (pairs.empty()) return "no (wavelength, value) pairs";
    if (pairs.size() / 2 > kMaxSpectrumPairs) return "over " + std::to_string(kMaxSpectrumPairs) + " pairs, the limit";
    if (pairs.size() % 2 != 0)
        return std::to_string(pairs.size()) + " numbers, an odd count: a spectrum is (wavelength, value) pairs";
    for (std::size_t i = 0; i < pairs.size(); ++i)
        if (!std::isfinite(pairs[i])) return number_place(lines, i) + "a number that is not finite";
    for (std::size_t i = 2; i < pairs.size(); i += 2)
        if (!(pairs[i] > pairs[i - 2]))
            return number_place(lines, i) + "wavelength " + short_number(pairs[i]) + " after " + short_number(pairs[i - 2]) +
                   ": wavelengths must increase";
    return "";
}

std::vector<double> parse_spectrum_file(std::string_view text, std::string& error) {
    std::vector<double> pairs;
    std::vector<int> lines;
    int line = 1;
    std::size_t i = 0;
    error.clear();
    while (i < text.size()) {
        const char c = text[i];
        if (c == '\n') ++line;
        if (c == '#') {
            while (i < text.size() && text[i] != '\n') ++i;
            continue;
        }
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == ',' || c == '\f' || c == '\v') {
            ++i;
            continue;
        }
        const std::size_t start = i;
        while (i < text.size() && std::string_view(" \t\r\n,\f\v#").find(text[i]) == std::string_view::npos) ++i;
        const std::string_view word = text.substr(start, i - start);
        double x = 0.0;
        if (!spectrum_number(word, x)) {
            error = "line " + std::to_string(line) + ": \"" + excerpt(word, 24) + "\" is not a finite number";
            return {};
        }
        pairs.push_back(x);
        lines.push_back(line);
        if (pairs.size() > 2 * kMaxSpectrumPairs + 1) break;  // over the limit: said below
    }
    error = check_spectrum_pairs(pairs, &lines);
    if (!error.empty()) return {};
    return pairs;
}

bool is_named_spectrum(const std::string& value) {
    std::string part;
    return named_metal(value, part) || named_glass_ior(value) || value.rfind("stdillum-", 0) == 0 || value.rfind("illum-", 0) == 0;
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
