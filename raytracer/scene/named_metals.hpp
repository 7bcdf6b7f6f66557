#pragma once
// The named conductors a scene may give as {"type": "conductor", "metal": "<name>"}: pbrt-v4's
// named spectra metal-<name>-eta / metal-<name>-k reduced to RGB eta and k (linear sRGB channels).
// The reduction (tools/conductor_rgb.py prints this table) and its measured error are in
// docs/conductors.md: per channel, the spectral Fresnel reflectance weighted by the channel's
// CIE-derived sensitivity, fitted by one (eta, k) exact at normal incidence.
#include <optional>
#include <span>
#include <string_view>

#include <glm/vec3.hpp>

namespace sweeptrace {

struct NamedMetal {
    std::string_view name;
    glm::vec3 eta, k;
};

// Every named metal, in the order messages list them.
std::span<const NamedMetal> named_metals();
// The metal of that name (case-sensitive, as pbrt spells them), or nullopt.
std::optional<NamedMetal> find_named_metal(std::string_view name);

}  // namespace sweeptrace
