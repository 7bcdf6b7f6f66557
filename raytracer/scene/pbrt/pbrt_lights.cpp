// pbrt-v4's LightSource statements as our "lights" and "background" (scenes/README.md "Lights",
// "Environment"). Brightness: pbrt-v4 divides each light's spectrum by its luminance-per-unit
// (for "rgb" values: by the colour space illuminant's, so rgb stays rgb) and multiplies "scale";
// "power" (point, spot) and "illuminance" (distant, infinite) then set the scale from the
// illuminant's luminance 1: intensity = I power / (4 pi) for a point, I power / (2 pi (1 - (cos
// start + cos end) / 2)) for a spot, irradiance = L illuminance for a distant light, radiance =
// L illuminance / pi for a constant infinite light.
//
// Environment maps. pbrt-v4's image infinite light reads a square image in its equal-area
// octahedral mapping: our environment's "mapping": "equal-area", whose frame is pbrt's light
// space turned by `Rotate -90 1 0 0` ((x, y, z)_pbrt = (x, -z, y)_ours, render/lights/environment_light.hpp).
// A 2:1 image is taken as pbrt-v3's equirectangular map: +z up in light space, u = phi / 2 pi from
// +x toward +y, v = theta / pi from +z; ours has +y up, u = 0.5 from -z, turning right-handed
// toward +x; as maps of directions the two differ by (x, y, z)_pbrt = (z, -x, y)_ours, a mirror,
// which our environment's "mirror" undoes. With the light's transform, the map's frame is written
// as our "mirror" and "rotate": a number when the turn is about +y, else {axis, degrees} (a z-up
// world's map, a tilted one); only a light transform that shears is no rotation, and then the
// nearest turn about +y is used and the warning says so.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include "raytracer/input_error.hpp"
#include "raytracer/scene/load_image_file.hpp"
#include "raytracer/scene/pbrt/pbrt_transform.hpp"
#include "raytracer/scene/pbrt/pbrt_world.hpp"

namespace sweeptrace::pbrt {

using nlohmann::json;

namespace {


json vec(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

void add_background(WorldContext& w, const Where& at, const glm::dvec3& radiance) {
    json& bg = w.doc["background"];
    if (bg.is_null()) {
        bg = {{"color", vec(radiance)}};
    } else if (bg.contains("color")) {
        const glm::dvec3 old(bg["color"][0].get<double>(), bg["color"][1].get<double>(), bg["color"][2].get<double>());
        bg["color"] = vec(old + radiance);
    } else {
        w.diag.warn(at, "two infinite lights", "a second infinite light beside an environment map is not supported (ignored)");
    }
}

// pbrt-v4's "portal", four points in the light's space, as our background's "portal" in the
// world (render/lights/portal.hpp; the loader checks it is a rectangle, as pbrt-v4 does). It only guides
// next event estimation; pbrt-v4 also darkens the sky behind the portal's plane, which we do not.
void add_portal(WorldContext& w, const LightRecord& l, const std::string& what) {
    const ParamList& p = l.statement.params;
    Diagnostics& d = w.diag;
    const Where& at = l.statement.where;
    if (!p.has("portal")) return;
    const std::vector<double> v = p.get_floats("portal", d);
    if (v.size() != 12) d.fail(at, what + ": \"portal\" must be 4 points (12 numbers), got " + std::to_string(v.size()) + " numbers");
    if (!w.doc.contains("background") || w.doc["background"].is_null()) return;  // the light was dropped
    json& bg = w.doc["background"];
    if (bg.contains("portal")) {
        d.warn(at, "two portals", what + ": a second portal is not supported (the first is kept)");
        return;
    }
    json corners = json::array();
    for (std::size_t i = 0; i < 4; ++i)
        corners.push_back(vec(glm::dvec3(l.ctm * glm::dvec4(v[3 * i], v[3 * i + 1], v[3 * i + 2], 1.0))));
    bg["portal"] = corners;
}

void infinite_background(WorldContext& w, const LightRecord& l, const std::string& what, double scale) {
    const ParamList& p = l.statement.params;
    Diagnostics& d = w.diag;
    const Where& at = l.statement.where;
    const double illuminance = p.get_float("illuminance", -1.0, d);
    std::string file = p.get_string("filename", "", d);
    // pbrt-v3 named the map "mapname" and let "L" multiply it (pbrt-v4's --upgrade renames the
    // one and folds a grey "L" into "scale"). Read as a constant light instead, such a file's sky
    // was a uniform white background (L's default), bright even where its map is black.
    const bool v3_map = file.empty() && p.has("mapname");
    if (v3_map) {
        file = p.get_string("mapname", "", d);
        if (p.has("L")) {
            const glm::dvec3 l = w.materials.emitted(p, "L", what);
            const double mean = (l.x + l.y + l.z) / 3.0;
            if (l.x != l.y || l.y != l.z)
                d.warn(at, "environment tint", what + ": a coloured \"L\" on a map is not supported (its mean, " + std::to_string(mean) + ", scales the map)");
            scale *= mean;
        }
    }
    if (file.empty()) {
        glm::dvec3 radiance = w.materials.emitted(p, "L", what) * scale;
        if (illuminance > 0.0) radiance *= illuminance / kPi;
        add_background(w, at, radiance);
        return;
    }
    if (!v3_map && p.has("L")) d.fail(at, what + ": give either \"L\" or \"filename\", not both");
    if (illuminance > 0.0) d.warn(at, "environment illuminance", what + ": \"illuminance\" with an image is not supported (\"scale\" alone used)");
    const std::filesystem::path path = w.files.resolve(file);
    const std::shared_ptr<const Image> image =
        read_image_path(file, path, "environment image", [&](const std::string& m) { d.fail(at, what + ": " + m); });
    const bool equal_area = image->width == image->height;
    if (!w.doc["background"].is_null()) {
        d.warn(at, "two infinite lights", "a second infinite light beside another is not supported (ignored)");
        return;
    }
    // Our direction d (the world is pbrt's) -> pbrt's light space: inverse(ctm) * d; it must equal
    // P * S * Ry(-rotate) * d with P our map frame in pbrt's terms and S our "mirror" (x -> -x, or
    // none). So S * Ry(-rotate) = P^-1 * inverse(ctm), whose determinant says whether S is needed.
    glm::dmat3 p_map(0.0);  // columns: images of our x, y, z
    if (equal_area) {
        p_map[0] = {1.0, 0.0, 0.0};
        p_map[1] = {0.0, 0.0, 1.0};
        p_map[2] = {0.0, -1.0, 0.0};
    } else {
        p_map[0] = {0.0, -1.0, 0.0};
        p_map[1] = {0.0, 0.0, 1.0};
        p_map[2] = {1.0, 0.0, 0.0};
    }
    glm::dmat3 light(l.ctm);
    const double s = std::cbrt(std::fabs(glm::determinant(light)));
    if (s > 0.0) light /= s;
    glm::dmat3 q = glm::inverse(p_map) * glm::inverse(light);
    const bool mirror = glm::determinant(q) < 0.0;
    if (mirror)
        for (int c = 0; c < 3; ++c) q[c][0] = -q[c][0];  // S * q: S is its own inverse
    // Ry(a) has columns (cos a, 0, -sin a), (0, 1, 0), (sin a, 0, cos a); q should be Ry(-rotate).
    const double a = std::atan2(-q[0][2], q[0][0]);
    glm::dmat3 ry(1.0);
    ry[0] = {std::cos(a), 0.0, -std::sin(a)};
    ry[2] = {std::sin(a), 0.0, std::cos(a)};
    double err = 0.0;
    for (int c = 0; c < 3; ++c) err = std::max(err, glm::length(q[c] - ry[c]));
    json env{{"file", w.files.json_path(file)}, {"rotate", -a * 180.0 / kPi}};
    if (err > 1e-9) {
        // Not a turn about +y (a z-up world's map, or a tilted one): the whole turn R = q^T, as
        // our "rotate" with an axis, when q is a rotation; a light transform that shears is not.
        const glm::dmat3 r = glm::transpose(q);
        double ortho = 0.0;
        const glm::dmat3 rtr = glm::transpose(r) * r;
        for (int c = 0; c < 3; ++c) ortho = std::max(ortho, glm::length(rtr[c] - glm::dmat3(1.0)[c]));
        if (ortho > 1e-6) {
            d.warn(at, "environment orientation", what + ": the light's transform shears the map (not a rotation): the nearest turn about +y is used");
        } else {
            glm::dvec3 axis;
            double degrees = 0.0;
            axis_angle(r, axis, degrees);
            env["rotate"] = {{"axis", {axis.x, axis.y, axis.z}}, {"degrees", degrees}};
        }
    }
    if (equal_area) env["mapping"] = "equal-area";
    if (mirror) env["mirror"] = true;
    if (scale != 1.0) env["scale"] = scale;
    w.doc["background"] = {{"environment", env}};
}

void infinite(WorldContext& w, const LightRecord& l, const std::string& what, double scale) {
    infinite_background(w, l, what, scale);
    add_portal(w, l, what);
}

// A light's value is a product of pbrt parameters; each may be a float while the product is not.
// Said here, at the LightSource's line and by the parameters' names, before the translated scene
// could only name its own JSON key.
void require_float_product(const Diagnostics& d, const Where& at, const std::string& what, const std::string& product,
                           const glm::dvec3& v) {
    for (int c = 0; c < 3; ++c) {
        if (std::fabs(v[c]) <= static_cast<double>(std::numeric_limits<float>::max())) continue;
        char value[32];
        std::snprintf(value, sizeof value, "%g", v[c]);
        d.fail(at, what + ": " + product + " is " + value + ", too large for single precision");
    }
}

}  // namespace

void write_light(WorldContext& w, const LightRecord& l) {
    const Statement& s = l.statement;
    const ParamList& p = s.params;
    Diagnostics& d = w.diag;
    const std::string what = "LightSource \"" + excerpt(s.type) + "\"";
    const glm::dmat4& m = l.ctm;
    double scale = p.get_float("scale", 1.0, d);
    auto point_of = [&](const char* name, const glm::dvec3& fallback) {
        return glm::dvec3(m * glm::dvec4(p.get_point3(name, d).value_or(fallback), 1.0));
    };
    json light;
    if (s.type == "point" || s.type == "spot") {
        const glm::dvec3 from = point_of("from", glm::dvec3(0.0));
        glm::dvec3 intensity = w.materials.emitted(p, "I", what) * scale;
        const double power = p.get_float("power", -1.0, d);
        light = {{"type", s.type}, {"position", vec(from)}};
        if (s.type == "point") {
            if (power > 0.0) intensity *= power / (4.0 * kPi);
        } else {
            const glm::dvec3 to = point_of("to", glm::dvec3(0.0, 0.0, 1.0));
            double cone = p.get_float("coneangle", 30.0, d);
            const double delta = p.get_float("conedeltaangle", 5.0, d);
            if (!(cone > 0.0)) d.fail(s.where, what + ": \"coneangle\" must be > 0");
            if (cone > 90.0) {
                d.warn(s.where, "spot over 90", what + ": a cone wider than 90 degrees is narrowed to 90 (our limit)");
                cone = 90.0;
            }
            const double start = std::clamp(cone - delta, 0.0, cone);
            if (power > 0.0) {
                const double cs = std::cos(start * kPi / 180.0), ce = std::cos(cone * kPi / 180.0);
                intensity *= power / (2.0 * kPi * ((1.0 - cs) + (cs - ce) / 2.0));
            }
            if (to == from) d.fail(s.where, what + ": \"from\" and \"to\" must differ");
            light["direction"] = vec(to - from);
            light["cone_angle"] = cone;
            light["falloff_start"] = start;
        }
        require_float_product(d, s.where, what, power > 0.0 ? "\"I\" x \"scale\" x \"power\"" : "\"I\" x \"scale\"", intensity);
        light["intensity"] = vec(intensity);
        if (intensity == glm::dvec3(0.0)) {
            d.warn(s.where, "black light", what + ": emits nothing (left out)");
            light = nullptr;
        }
    } else if (s.type == "distant") {
        const glm::dvec3 from = point_of("from", glm::dvec3(0.0)), to = point_of("to", glm::dvec3(0.0, 0.0, 1.0));
        glm::dvec3 irradiance = w.materials.emitted(p, "L", what) * scale;
        if (const double e = p.get_float("illuminance", -1.0, d); e > 0.0) irradiance *= e;
        if (to == from) d.fail(s.where, what + ": \"from\" and \"to\" must differ");
        require_float_product(d, s.where, what, "\"L\" x \"scale\" x \"illuminance\"", irradiance);
        light = {{"type", "directional"}, {"direction", vec(to - from)}, {"irradiance", vec(irradiance)}};
        if (irradiance == glm::dvec3(0.0)) {
            d.warn(s.where, "black light", what + ": emits nothing (left out)");
            light = nullptr;
        }
    } else if (s.type == "infinite") {
        infinite(w, l, what, scale);
    } else {
        d.warn(s.where, "light " + s.type, what + " is not supported (ignored)");
        for (const Param& q : p.params) q.used = true;
    }
    if (!light.is_null()) {
        light["name"] = what + " (" + s.where.short_text() + ")";
        w.doc["lights"].push_back(light);
    }
    p.warn_unused(what, d);
}

}  // namespace sweeptrace::pbrt
