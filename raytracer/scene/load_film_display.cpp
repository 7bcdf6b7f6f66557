#include "raytracer/scene/load_film_display.hpp"

#include <string>

namespace sweeptrace {

void read_film_display(const scene_json::Node& node, Film& film) {
    // 2^+-64 spans any radiance float can hold and then some; beyond it is a typo.
    if (auto e = node.find("exposure")) film.exposure = e->number_in(-64.0f, 64.0f);
    if (auto t = node.find("tone_curve")) {
        const std::string curve = t->string();
        if (curve == "clamp") film.tone_curve = ToneCurve::Clamp;
        else if (curve == "aces") film.tone_curve = ToneCurve::Aces;
        else t->fail("unknown tone curve \"" + curve + "\" (known: clamp, aces)");
    }
}

}  // namespace sweeptrace
