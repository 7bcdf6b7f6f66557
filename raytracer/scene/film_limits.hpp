#pragma once
// The ranges of the render's settings, wherever a value comes from: the scene file (film.width,
// film.spp, ...) or a command-line override (--width, --spp, ...). Both go through
// film_setting_problem, so an override cannot bypass what the scene file must meet.
//
// Generous limits that catch typos (an extra zero) before they turn into an hour-long render or a
// failed allocation; nothing real comes near them. Memory is checked separately, on the final
// size (cli/memory_budget.hpp).
#include <cstdint>
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

}  // namespace sweeptrace
