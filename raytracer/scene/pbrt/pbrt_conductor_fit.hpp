#pragma once
// A conductor's spectral eta(lambda) and k(lambda) as the RGB eta and k our conductor takes, by the
// reduction that made the named metals' table (docs/conductors.md; tools/conductor_rgb.py is its
// Python twin, `reduce_metal`, and this is the same computation step for step, so the same data gives
// the same numbers). Per linear-sRGB channel c:
//   1. weights w_c(lambda) = (M_sRGB . xyz_bar(lambda))_c over 380..780 nm every nm (illuminant E,
//      pbrt_spectra.hpp's CIE fit), normalised so that a flat reflectance 1 gives 1;
//   2. the target T_c(theta) = sum w_c R(theta, eta(lambda), k(lambda)), R the exact unpolarised
//      Fresnel reflectance of eta + i k (the textbook complex form), theta the midpoints of 90
//      one-degree steps, the data linearly interpolated and held at its ends;
//   3. (eta_c, k_c) exact at normal incidence (k_c from eta_c and T_c(0) in closed form), eta_c
//      minimising the cosine-weighted squared error over theta: the best of 700 geometric steps
//      0.01 * 1.01^i, then 60 golden-section steps in the bracket around it. Where no k >= 0
//      fits (a dielectric's channel), k_c = 0 and eta_c from T_c(0).
// Error: that of the table (docs/conductors.md, at most 0.019 in reflectance at any angle for gold's
// red, under 0.004 elsewhere). Degenerate input: eta below 1e-4 is raised to it and k below 0 to 0
// at each wavelength (the Fresnel term needs n != 0); T_c(0) is kept within [0, 0.9999] (1 would
// need an infinite k). Cost: about 260,000 complex Fresnel terms, 10 ms (-O2, 2026-12-03).
#include <vector>

#include <glm/vec3.hpp>

namespace sweeptrace::pbrt {

struct ConductorRgb {
    glm::dvec3 eta, k;
    glm::dvec3 normal_reflectance;  // T_c(0), what the fit meets exactly
};

// `eta_pairs` and `k_pairs`: interleaved (wavelength nm, value) pairs, wavelengths increasing, at
// least one pair each (pbrt_spectra.hpp: check_spectrum_pairs).
ConductorRgb fit_conductor_rgb(const std::vector<double>& eta_pairs, const std::vector<double>& k_pairs);

// Whether the pairs span the 380..780 nm the weights cover (else the ends are held: pbrt-v4
// itself reads 0 past them).
bool covers_visible(const std::vector<double>& pairs);

}  // namespace sweeptrace::pbrt
