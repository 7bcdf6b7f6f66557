#include "raytracer/scene/named_metals.hpp"

#include <array>

namespace sweeptrace {

namespace {

// python3 tools/conductor_rgb.py, 2026-12-03.
// Normal-incidence RGB reflectance in the comments. Sources of the spectra (as pbrt-v4 tabulates
// them): Ag, Al, Au, Cu on a 0.05 eV grid, 298-886 nm; CuZn (brass) every 10 nm, 290-890 nm; MgO and
// TiO2 dielectrics (k = 0 in the visible; their small k here is the reduction's negative-lobe
// residue, below 0.013).
constexpr std::array kMetals = {
    NamedMetal{"Ag", {0.1280f, 0.1256f, 0.1528f}, {3.9841f, 3.3817f, 2.3908f}},    // 0.970 0.961 0.913
    NamedMetal{"Al", {1.3805f, 0.9360f, 0.5826f}, {7.6418f, 6.6256f, 5.3273f}},    // 0.914 0.921 0.925
    NamedMetal{"Au", {0.4769f, 0.3938f, 1.6048f}, {17.1602f, 2.3489f, 1.7027f}},   // 0.994 0.789 0.337
    NamedMetal{"Cu", {0.2152f, 0.9697f, 1.2222f}, {3.3762f, 2.6244f, 2.3544f}},    // 0.933 0.640 0.534
    NamedMetal{"CuZn", {0.4644f, 0.5191f, 1.1520f}, {3.9468f, 2.6878f, 1.7962f}},  // 0.895 0.782 0.414
    NamedMetal{"MgO", {1.7344f, 1.7408f, 1.7540f}, {0.0021f, 0.0038f, 0.0041f}},   // 0.072 0.073 0.075
    NamedMetal{"TiO2", {2.8695f, 2.9544f, 3.1950f}, {0.0129f, 0.0000f, 0.0129f}},  // 0.233 0.244 0.274
};

}  // namespace

std::span<const NamedMetal> named_metals() { return kMetals; }

std::optional<NamedMetal> find_named_metal(std::string_view name) {
    for (const NamedMetal& m : kMetals)
        if (m.name == name) return m;
    return std::nullopt;
}

}  // namespace sweeptrace
