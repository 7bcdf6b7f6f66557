#pragma once
// The ranges of the render's settings, wherever a value comes from: the scene file (film.width,
// film.spp, ...) or a command-line override (--width, --spp, ...). Both go through
// film_setting_problem, so an override cannot bypass what the scene file must meet.
//
// Generous limits that catch typos (an extra zero) before they turn into an hour-long render or a
// failed allocation; nothing real comes near them. Memory is checked separately, on the final
// size (cli/memory_budget.hpp).
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace sweeptrace {

enum class FilmSetting { Width, Height, Spp, MaxDepth };

struct SettingRange {
    std::int64_t lo, hi;
};

constexpr SettingRange film_range(FilmSetting s) {
    switch (s) {
    case FilmSetting::Width:
    case FilmSetting::Height: return {1, 16384};
    case FilmSetting::Spp: return {1, 1 << 20};
    case FilmSetting::MaxDepth: return {1, 1024};
    }
    return {1, 1};
}

// Empty when `value` is in range, else "must be in [lo, hi], got value".
inline std::string film_setting_problem(FilmSetting s, std::int64_t value) {
    const SettingRange r = film_range(s);
    if (value >= r.lo && value <= r.hi) return {};
    return "must be in [" + std::to_string(r.lo) + ", " + std::to_string(r.hi) + "], got " + std::to_string(value);
}

// vcm's first merging radius r_1 (film.vcm_radius, a pbrt sppm Integrator's "radius"): the range
// in which every iteration's radius r_i keeps its merging density pi r_i^2 N (N pixels) and its
// kernel 1 / (pi r_i^2) finite, non-zero floats, and the photon grid's cells (2 r_i) finite. The
// schedule only shrinks the radius, by at most spp^(-1/2) (r_i = r_1 (i + 1)^((alpha - 1) / 2) for
// any alpha in [0, 1], render/integrators/vcm.hpp), so over the spp limit r_i >= r_1 / 1024:
//   lo = 1024 sqrt(FLT_MIN)             (r_i^2 a normal float: about 1.1e-16)
//   hi = sqrt(FLT_MAX / (pi 16384^2))   (pi r_1^2 N finite at the largest film: about 6.3e14)
// Outside it the render would end in an internal error or count most samples as non-finite.
struct RadiusRange {
    float lo, hi;
};
inline RadiusRange vcm_radius_range() {
    const double shrink = std::sqrt(double(film_range(FilmSetting::Spp).hi));
    const double side = double(film_range(FilmSetting::Width).hi);
    const double pi = 3.14159265358979323846;
    return {static_cast<float>(shrink * std::sqrt(double(std::numeric_limits<float>::min()))),
            static_cast<float>(std::sqrt(double(std::numeric_limits<float>::max()) / (pi * side * side)))};
}

}  // namespace sweeptrace
