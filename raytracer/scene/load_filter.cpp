#include "raytracer/scene/load_filter.hpp"

#include <string>

namespace sweeptrace {

namespace {
// A filter wider than this many pixels is a typo (and would blur the image to nothing).
constexpr float kMaxRadius = 16.0f;
}  // namespace

FilterSpec read_filter(const scene_json::Node& node) {
    if (!node.value().is_object()) node.fail("must be an object with a \"type\" (box, tent, gaussian, mitchell)");
    const scene_json::Node type_node = node.at("type");
    const std::string type = type_node.string();
    FilterSpec f;
    if (type == "box") {
        node.require_object({"type", "radius"});
        f.type = FilterSpec::Type::Box;
        f.radius = 0.5f;
    } else if (type == "tent") {
        node.require_object({"type", "radius"});
        f.type = FilterSpec::Type::Tent;
        f.radius = 1.0f;
    } else if (type == "gaussian") {
        node.require_object({"type", "radius", "sigma"});
        f.type = FilterSpec::Type::Gaussian;
        f.radius = 1.5f;
        if (auto s = node.find("sigma")) f.sigma = s->number_in(0.05f, kMaxRadius);
    } else if (type == "mitchell") {
        node.require_object({"type", "radius", "b", "c"});
        f.type = FilterSpec::Type::Mitchell;
        f.radius = 2.0f;
        if (auto b = node.find("b")) f.b = b->number_in(0.0f, 1.0f);
        if (auto c = node.find("c")) f.c = c->number_in(0.0f, 1.0f);
    } else {
        type_node.fail("unknown filter type \"" + type + "\" (known: box, tent, gaussian, mitchell)");
    }
    if (auto r = node.find("radius")) {
        f.radius = r->number_in(0.0f, kMaxRadius);
        if (!(f.radius >= 0.05f)) r->fail("must be in [0.05, 16] pixels, got " + r->shown());
    }
    return f;
}

}  // namespace sweeptrace
