#include "raytracer/scene/pbrt/pbrt_world.hpp"

#include <cmath>

#include <glm/matrix.hpp>
#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include "raytracer/input_error.hpp"
#include "raytracer/scene/pbrt/pbrt_transform.hpp"

namespace sweeptrace::pbrt {

using nlohmann::json;

std::optional<json> transform_json(const glm::dmat4& m) {
    const std::optional<AffineSteps> s = split_affine(m);
    if (!s) return std::nullopt;
    json steps = json::array();
    auto rotate = [&](const glm::dmat3& r) {
        glm::dvec3 axis;
        double degrees = 0.0;
        axis_angle(r, axis, degrees);
        if (degrees != 0.0) steps.push_back({{"rotate", {{"axis", {axis.x, axis.y, axis.z}}, {"degrees", degrees}}}});
    };
    rotate(s->pre_rotation);
    if (s->scale != glm::dvec3(1.0)) {
        if (s->scale.x == s->scale.y && s->scale.y == s->scale.z) steps.push_back({{"scale", s->scale.x}});
        else steps.push_back({{"scale", {s->scale.x, s->scale.y, s->scale.z}}});
    }
    rotate(s->rotation);
    if (s->translation != glm::dvec3(0.0))
        steps.push_back({{"translate", {s->translation.x, s->translation.y, s->translation.z}}});
    return steps;
}

std::optional<std::string> WorldContext::material_for(const ShapeRecord& s, double area) {
    const auto it = scene.materials.find(s.material);
    if (it == scene.materials.end())
        diag.fail(s.statement.where, "NamedMaterial \"" + excerpt(s.material) + "\": no material of that name (define it with MakeNamedMaterial)");
    const bool invisible = scene.invisible.at(s.material);
    if (!s.area_light) {
        if (invisible) {
            // pbrt's "interface": nothing for light, only a boundary between two media; without
            // one (the same medium on both sides) the shape is left out.
            if (s.inside == s.outside) return std::nullopt;
            doc["materials"][s.material] = {{"type", "interface"}};
            return s.material;
        }
        doc["materials"][s.material] = it->second;
        return s.material;
    }
    const Statement& light = s.area_light->statement;
    const ParamList& p = light.params;
    const std::string what = "AreaLightSource \"" + excerpt(light.type) + "\"";
    if (light.type != "diffuse") {
        diag.warn(light.where, "area light " + light.type, what + " is not supported (the shape does not emit)");
        for (const Param& q : p.params) q.used = true;
        if (invisible) return std::nullopt;
        doc["materials"][s.material] = it->second;
        return s.material;
    }
    glm::dvec3 l = materials.emitted(p, "L", what) * p.get_float("scale", 1.0, diag);
    const bool two_sided = p.get_bool("twosided", false, diag);
    std::string key = s.material + " + light (" + light.where.short_text() + ")";
    if (const double power = p.get_float("power", -1.0, diag); power > 0.0) {
        // pbrt-v4: radiance scaled so the shape emits `power` watts: L * power / (sides pi area),
        // the spectrum's own brightness normalised to 1 for rgb (its illuminant's).
        if (area > 0.0) l *= power / ((two_sided ? 2.0 : 1.0) * 3.14159265358979323846 * area);
        key += " shape (" + s.statement.where.short_text() + ")";
    }
    if (p.has("filename")) {
        p.find("filename");
        diag.warn(light.where, "area light image", what + ": an emission image \"filename\" is not supported (ignored: uniform L)");
    }
    p.warn_unused(what, diag);
    json m = invisible ? json{{"type", "emissive"}} : it->second;
    if (l == glm::dvec3(0.0)) {
        if (invisible) return std::nullopt;
        doc["materials"][s.material] = it->second;
        return s.material;
    }
    m["emission"] = {l.r, l.g, l.b};
    if (two_sided) m["two_sided"] = true;
    doc["materials"][key] = m;
    if (origins) origins->materials.try_emplace(key, ObjectOrigin{light.where, what});
    return key;
}

void scale_emitters(json& doc, double k) {
    auto times = [k](json& v) {
        if (v.is_number()) v = v.get<double>() * k;
        else
            for (json& x : v) x = x.get<double>() * k;
    };
    for (auto& [name, m] : doc["materials"].items())
        if (m.contains("emission")) times(m["emission"]);
    if (doc.contains("lights"))
        for (json& l : doc["lights"])
            for (const char* key : {"intensity", "irradiance"})
                if (l.contains(key)) times(l[key]);
    if (doc.contains("background")) {
        json& bg = doc["background"];
        if (bg.contains("color")) times(bg["color"]);
        if (bg.contains("environment")) bg["environment"]["scale"] = bg["environment"].value("scale", 1.0) * k;
    }
}

json write_world(const PbrtScene& scene, MaterialTranslator& materials, const FileNames& files, Diagnostics& diag,
                 std::string& film_filename, DocumentOrigins& origins) {
    WorldContext w{scene, materials, files, diag, nlohmann::json::object(), 0};
    w.doc = json::object();
    w.origins = &origins;
    w.doc["description"] = "converted from the pbrt-v4 scene " + scene.main_file.filename().string() + " by sweeptrace";
    w.doc["materials"] = json::object();
    w.doc["objects"] = json::array();
    write_camera_and_film(w, film_filename);
    const auto origin = [](const Statement& s, const char* directive) {
        return ObjectOrigin{s.where, std::string(directive) + " \"" + excerpt(s.type) + "\""};
    };
    const Where top{std::make_shared<const std::string>(scene.main_file.string()), 1};
    origins.camera = scene.camera ? origin(*scene.camera, "Camera") : ObjectOrigin{top, "Camera (the default)"};
    origins.film = scene.film ? origin(*scene.film, "Film") : ObjectOrigin{top, "Film (the default)"};
    for (const auto& [name, where] : scene.material_where) origins.materials[name] = {where, "material \"" + excerpt(name) + "\""};
    for (const auto& [name, where] : scene.medium_where) origins.media[name] = {where, "MakeNamedMedium \"" + excerpt(name) + "\""};
    if (!scene.media.empty()) w.doc["media"] = scene.media;
    if (!scene.camera_medium.empty()) w.doc["camera"]["medium"] = scene.camera_medium;
    for (const ShapeRecord& s : scene.shapes) {
        const std::size_t before = w.doc["objects"].size();
        write_shape(w, s);
        // A boundary between media (scene/load_media.hpp), named by its statement (as lights are)
        // for the nesting check's message (render/media/media_nesting.hpp).
        if (s.inside != s.outside)
            for (std::size_t i = before; i < w.doc["objects"].size(); ++i) {
                if (!s.inside.empty()) w.doc["objects"][i]["inside"] = s.inside;
                if (!s.outside.empty()) w.doc["objects"][i]["outside"] = s.outside;
                w.doc["objects"][i]["name"] = origin(s.statement, "Shape").what + " (" + s.statement.where.short_text() + ")";
            }
        if (const std::size_t n = w.doc["objects"].size(); n > origins.objects.size()) origins.objects.resize(n, origin(s.statement, "Shape"));
    }
    const auto has = [&](const char* key) { return w.doc.contains(key) && !w.doc[key].is_null(); };
    for (const LightRecord& l : scene.lights) {
        const bool had_background = has("background");
        write_light(w, l);
        if (const std::size_t n = has("lights") ? w.doc["lights"].size() : 0; n > origins.lights.size())
            origins.lights.resize(n, origin(l.statement, "LightSource"));
        if (!had_background && has("background")) origins.background = origin(l.statement, "LightSource");
    }
    if (w.imaging_ratio != 1.0) scale_emitters(w.doc, w.imaging_ratio);
    return w.doc;
}

}  // namespace sweeptrace::pbrt
