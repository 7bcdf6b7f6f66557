#include "raytracer/scene/load_lights.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>

namespace sweeptrace {

namespace {

using scene_json::Node;

constexpr float kDegree = 3.14159265358979323846f / 180.0f;

// A light must give off something: all components >= 0, one of them > 0.
glm::vec3 read_power(const Node& node) {
    const glm::vec3 v = node.vec3_at_least(0.0f);
    if (v == glm::vec3(0.0f)) node.fail("a light must emit: some component must be > 0");
    return v;
}

void read_spot(const Node& node, SceneLight& l) {
    l.direction = glm::normalize(node.at("direction").nonzero_vec3());
    const Node cone = node.at("cone_angle");
    const float cone_deg = cone.number_in(0.0f, 90.0f);
    if (!(cone_deg > 0.0f)) cone.fail("must be a half-angle in degrees in (0, 90], got " + cone.shown());
    // pbrt's default: the falloff takes the outer 5 degrees of the cone.
    float start_deg = std::max(0.0f, cone_deg - 5.0f);
    if (auto start = node.find("falloff_start")) start_deg = start->number_in(0.0f, cone_deg);
    l.cos_cone = std::cos(cone_deg * kDegree);
    l.cos_falloff_start = std::cos(start_deg * kDegree);
}

SceneLight read_light(const Node& node) {
    if (!node.value().is_object()) node.fail("must be an object with a \"type\"");
    const Node type_node = node.at("type");
    const std::string type = type_node.string();
    SceneLight l;
    if (type == "point") {
        node.require_object({"type", "name", "position", "intensity"});
        l.type = SceneLight::Type::Point;
    } else if (type == "spot") {
        node.require_object({"type", "name", "position", "intensity", "direction", "cone_angle", "falloff_start"});
        l.type = SceneLight::Type::Spot;
        read_spot(node, l);
    } else if (type == "directional") {
        node.require_object({"type", "name", "direction", "irradiance", "angular_diameter"});
        l.type = SceneLight::Type::Directional;
        l.direction = glm::normalize(node.at("direction").nonzero_vec3());
        l.irradiance = read_power(node.at("irradiance"));
        if (auto d = node.find("angular_diameter")) l.half_angle = 0.5f * d->number_in(0.0f, 90.0f) * kDegree;
    } else {
        type_node.fail("unknown light type \"" + type + "\" (known: point, spot, directional)");
    }
    if (l.type != SceneLight::Type::Directional) {
        l.position = node.at("position").vec3();
        l.intensity = read_power(node.at("intensity"));
    }
    l.name = node.has("name") ? node.at("name").string() : node.path() + " (" + type + ")";
    return l;
}

}  // namespace

std::vector<SceneLight> read_lights(const Node& node) {
    std::vector<SceneLight> lights;
    const std::size_t n = node.array_size();
    for (std::size_t i = 0; i < n; ++i) lights.push_back(read_light(node.element(i)));
    return lights;
}

}  // namespace sweeptrace
