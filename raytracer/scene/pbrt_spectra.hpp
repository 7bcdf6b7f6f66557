#pragma once
// pbrt-v4's spectra as the RGB our renderer works in (linear sRGB primaries, as pbrt's default
// colour space). What is exact and what is not:
//   rgb                  exact: pbrt-v4 renders an "rgb" reflectance or illuminant back to itself
//                        in its sRGB film (its RGB-to-spectrum tables round-trip).
//   blackbody T          pbrt-v4 normalises a light's spectrum to luminance 1 (then "scale"); here
//                        Planck's law times the CIE 1931 matching functions (the multi-lobe
//                        Gaussian fit of Wyman, Sloan and Shirley 2013) summed every 5 nm over
//                        360-830 nm, XYZ to linear sRGB, scaled to Y = 1: the chromaticity to
//                        about 1% of the tabulated functions'.
//   "stdillum-D65"       white (1, 1, 1): the colour space's own illuminant.
//   sampled pairs        approximated: the piecewise-linear spectrum read at 610, 550 and 465 nm.
//   named metals         kept by name for our conductor: those of scene/named_metals.hpp, all
//                        seven pbrt-v4 names (Ag Al Au Cu CuZn MgO TiO2).
//   named glasses        their index at the helium d line (587.6 nm), dispersion dropped.
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace sweeptrace::pbrt {

glm::dvec3 blackbody_rgb(double kelvin);  // luminance 1
glm::dvec3 sampled_rgb(const std::vector<double>& pairs);

// "metal-Au-eta" -> "Au" (and `part` "eta"); nullopt unless one of our named metals
// (scene/named_metals.hpp), which are the seven pbrt-v4 names.
std::optional<std::string> named_metal(const std::string& spectrum, std::string& part);
// "glass-BK7" -> 1.5168; nullopt for names we do not know.
std::optional<double> named_glass_ior(const std::string& spectrum);

// The metals known (scene/named_metals.hpp's, in its order), and for messages their pbrt names
// in one line: "metal-{Ag,Al,Au,Cu,CuZn,MgO,TiO2}-{eta,k}".
const std::vector<std::string>& known_metals();
std::string known_metal_spectra();

}  // namespace sweeptrace::pbrt
