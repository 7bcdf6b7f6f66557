#include "raytracer/cli/render_limits.hpp"

#include <cmath>
#include <limits>

#include "raytracer/input_error.hpp"
#include "raytracer/scene/film_limits.hpp"

namespace sweeptrace {

namespace {

// Decimal digits only, optionally signed: no "0x", no "1e3", no trailing junk.
std::optional<std::int64_t> parse_integer(const std::string& text) {
    std::size_t i = text.size() > 0 && (text[0] == '-' || text[0] == '+') ? 1 : 0;
    if (i == text.size() || text.size() > 20) return std::nullopt;
    for (std::size_t k = i; k < text.size(); ++k)
        if (text[k] < '0' || text[k] > '9') return std::nullopt;
    try {
        return std::stoll(text);
    } catch (const std::exception&) {
        return std::nullopt;  // beyond int64: out of every range below anyway
    }
}

[[noreturn]] void refuse(const char* option, const std::string& what) {
    throw InputError(std::string(option) + ": " + what);
}

std::int64_t checked_setting(const char* option, const std::string& text, FilmSetting setting) {
    const std::optional<std::int64_t> v = parse_integer(text);
    const SettingRange r = film_range(setting);
    if (!v)
        refuse(option, "must be an integer in [" + std::to_string(r.lo) + ", " + std::to_string(r.hi) + "], got '" +
                           excerpt(text, 30) + "'");
    if (const std::string problem = film_setting_problem(setting, *v); !problem.empty()) refuse(option, problem);
    return *v;
}

std::uint64_t checked_seed(const std::string& text) {
    const bool digits = !text.empty() && text.size() <= 20 &&
                        text.find_first_not_of("0123456789") == std::string::npos;
    std::uint64_t v = 0;
    bool fits = digits;
    if (digits) {
        try {
            v = std::stoull(text);
        } catch (const std::exception&) {
            fits = false;
        }
    }
    if (!fits) refuse("--seed", "must be an integer in [0, 18446744073709551615], got '" + excerpt(text, 30) + "'");
    return v;
}

// The side --width or --height leaves out, from the film's aspect ratio; in range or refused.
int derived_side(const char* given, std::int64_t value, int film_given, int film_other, FilmSetting other) {
    const double side = std::max(1.0, std::round(double(value) * film_other / film_given));
    const std::int64_t s = side > 1e15 ? std::numeric_limits<std::int64_t>::max() : static_cast<std::int64_t>(side);
    if (!film_setting_problem(other, s).empty())
        refuse(given, "keeping the film's aspect ratio (" + std::to_string(film_given) + " to " +
                          std::to_string(film_other) + ") makes the other side " + std::to_string(s) +
                          ", over the limit of " + std::to_string(film_range(other).hi) + "; give both --width and --height");
    return static_cast<int>(s);
}

}  // namespace

void RenderLimits::add_options(CLI::App& cmd) {
    spp_opt = cmd.add_option("--spp", spp, "Samples per pixel, 1..1048576 (default: the scene's film.spp)");
    width_opt = cmd.add_option("--width", width, "Image width, 1..16384; alone, the height follows the film's aspect ratio");
    height_opt = cmd.add_option("--height", height, "Image height, 1..16384; alone, the width follows the film's aspect ratio");
    cmd.add_option("--threads", threads, "Worker threads, 0 = all cores, at most 1024")->capture_default_str();
    seed_opt = cmd.add_option("--seed", seed, "Random seed, 0..2^64-1 (default: the scene's seed)");
    depth_opt = cmd.add_option("--max-depth", max_depth,
                               "Path vertices after the camera, 1..1024 (default: the scene's film.max_depth)");
    memory_opt = cmd.add_option("--max-memory", max_memory,
                                "Refuse a render whose estimated memory exceeds this (e.g. 2G, 512M; default: the "
                                "memory available, from /proc/meminfo and the cgroup limit)");
}

void RenderLimits::validate() const {
    if (width_opt->count()) checked_setting("--width", width, FilmSetting::Width);
    if (height_opt->count()) checked_setting("--height", height, FilmSetting::Height);
    if (spp_opt->count()) checked_setting("--spp", spp, FilmSetting::Spp);
    if (depth_opt->count()) checked_setting("--max-depth", max_depth, FilmSetting::MaxDepth);
    if (seed_opt->count()) checked_seed(seed);
    thread_count();
    memory_limit();
}

void RenderLimits::apply(Scene& scene) const {
    Film& film = scene.film;
    const int film_w = film.width, film_h = film.height;
    const bool w = width_opt->count() > 0, h = height_opt->count() > 0;
    if (w) film.width = static_cast<int>(checked_setting("--width", width, FilmSetting::Width));
    if (h) film.height = static_cast<int>(checked_setting("--height", height, FilmSetting::Height));
    if (w && !h) film.height = derived_side("--width", film.width, film_w, film_h, FilmSetting::Height);
    if (h && !w) film.width = derived_side("--height", film.height, film_h, film_w, FilmSetting::Width);
    if (spp_opt->count()) film.spp = static_cast<int>(checked_setting("--spp", spp, FilmSetting::Spp));
    if (depth_opt->count()) film.max_depth = static_cast<int>(checked_setting("--max-depth", max_depth, FilmSetting::MaxDepth));
    if (seed_opt->count()) scene.seed = checked_seed(seed);
}

int RenderLimits::thread_count() const {
    const std::optional<std::int64_t> v = parse_integer(threads);
    if (!v || *v < 0 || *v > kMaxThreads)
        refuse("--threads", "must be an integer in [0, " + std::to_string(kMaxThreads) + "] (0 = all cores), got '" +
                                excerpt(threads, 30) + "'");
    return static_cast<int>(*v);
}

std::optional<std::uint64_t> RenderLimits::memory_limit() const {
    if (!memory_opt->count()) return std::nullopt;
    const std::optional<std::uint64_t> v = parse_byte_size(max_memory);
    if (!v || *v == 0) refuse("--max-memory", "must be a size such as 2G, 512M or 1000000 (bytes), got '" + excerpt(max_memory, 30) + "'");
    return v;
}

std::optional<std::uint64_t> parse_byte_size(const std::string& text) {
    if (text.empty() || text.size() > 32) return std::nullopt;
    std::size_t used = 0;
    double v = 0.0;
    try {
        v = std::stod(text, &used);
    } catch (const std::exception&) {
        return std::nullopt;
    }
    if (text[0] < '0' || text[0] > '9') return std::nullopt;  // no sign, no "inf", no "nan"
    double unit = 1.0;
    const std::string suffix = text.substr(used);
    if (suffix == "k" || suffix == "K") unit = 1024.0;
    else if (suffix == "m" || suffix == "M") unit = 1024.0 * 1024.0;
    else if (suffix == "g" || suffix == "G") unit = 1024.0 * 1024.0 * 1024.0;
    else if (suffix == "t" || suffix == "T") unit = 1024.0 * 1024.0 * 1024.0 * 1024.0;
    else if (!suffix.empty()) return std::nullopt;
    const double bytes = v * unit;
    if (!(bytes >= 1.0 && bytes < 1.8e19)) return std::nullopt;
    return static_cast<std::uint64_t>(bytes);
}

}  // namespace sweeptrace
