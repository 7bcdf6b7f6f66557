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
//   sampled pairs        approximated: the piecewise-linear spectrum read at 610, 550 and 465 nm;
//                        but a conductor's eta and k both sampled are reduced together by the
//                        reflectance fit of the named metals (pbrt_conductor_fit.hpp).
//   spectrum files       a string that is not one of pbrt-v4's named spectra names a file of
//                        (wavelength nm, value) pairs (pbrt-v4: paramdict.cpp, readSpectrumFromFile;
//                        util/file.cpp, ReadFloatFile), read as sampled pairs (below).
//   named metals         kept by name for our conductor: those of scene/named_metals.hpp, all
//                        seven pbrt-v4 names (Ag Al Au Cu CuZn MgO TiO2).
//   named glasses        their index at the helium d line (587.6 nm), dispersion dropped.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

namespace sweeptrace::pbrt {

glm::dvec3 blackbody_rgb(double kelvin);  // luminance 1
glm::dvec3 sampled_rgb(const std::vector<double>& pairs);
// The piecewise-linear spectrum of (nm, value) pairs (wavelengths increasing) at `nm`, held
// constant past its ends (pbrt-v4 reads 0 there; a reflectance or an index held is kinder than 0).
double sampled_at(const std::vector<double>& pairs, double nm);

// The CIE 1931 2-degree matching functions (the multi-lobe fit of Wyman, Sloan and Shirley 2013) at
// `nm`, and XYZ to linear sRGB (D65 white).
glm::dvec3 cie_xyz_1931(double nm);
glm::dvec3 linear_srgb_from_xyz(const glm::dvec3& xyz);

// Spectrum files, pbrt-v4's format: numbers separated by white space (or commas), `#` to the end
// of a line a comment, read as interleaved (wavelength, value) pairs. Bounds: at most
// kMaxSpectrumFileBytes of text and kMaxSpectrumPairs pairs (a 1 nm table of 300-900 nm is 601).
inline constexpr std::uintmax_t kMaxSpectrumFileBytes = std::uintmax_t{1} << 20;  // 1 MiB
inline constexpr std::size_t kMaxSpectrumPairs = 100000;
// The pairs; empty with `error` set ("line 3: \"abc\" is not a finite number") unless the text holds at
// least one pair of finite numbers, an even count, wavelengths strictly increasing.
std::vector<double> parse_spectrum_file(std::string_view text, std::string& error);
// Why interleaved pairs are not a spectrum (none, an odd count, over kMaxSpectrumPairs, not
// finite, wavelengths not strictly increasing), or "" when they are one. `lines`, when given, holds
// each number's line in the file, for the message.
std::string check_spectrum_pairs(const std::vector<double>& pairs, const std::vector<int>* lines = nullptr);

// Whether pbrt-v4 reads the string value of a spectrum parameter as a named spectrum (a metal or
// glass we know, "stdillum-*", "illum-*") rather than as a spectrum file's name. (pbrt-v4 also
// names camera sensor curves, "canon_eos_100d_r" ...: meant for Film "sensor", here files.)
bool is_named_spectrum(const std::string& value);

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
