#include "raytracer/scene/pbrt/pbrt_media.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "raytracer/load_budget.hpp"
#include "raytracer/scene/pbrt/pbrt_world.hpp"
#include "raytracer/scene/vdb_grid.hpp"

namespace sweeptrace::pbrt {

using nlohmann::json;

namespace {

// The medium's transform: the current transformation matrix as our transform steps.
void write_transform(json& m, const Statement& s, const std::string& what, const glm::dmat4& ctm, Diagnostics& diag) {
    if (ctm == glm::dmat4(1.0)) return;
    const std::optional<json> steps = transform_json(ctm);
    if (!steps) diag.fail(s.where, what + ": its transformation mirrors or is singular (a grid's transform must be a rotation, scale and translation)");
    m["transform"] = *steps;
}

// pbrt-v4's NanoVDBMedium: its .nvdb file and grid, read by the scene loader.
void write_nanovdb(json& m, const Statement& s, const std::string& what, const FileNames& files, Diagnostics& diag) {
    const ParamList& p = s.params;
    const std::string filename = p.get_string("filename", "", diag);
    if (filename.empty()) diag.fail(s.where, what + ": a \"nanovdb\" medium needs \"string filename\" (its .nvdb file)");
    m["file"] = files.json_path(filename);
    m["grid"] = p.get_string("gridname", "density", diag);
    std::string lost;
    for (const char* key : {"temperaturename", "Lescale", "temperatureoffset", "temperaturecutoff", "temperaturescale"})
        if (p.find(key)) lost += std::string(lost.empty() ? "" : ", ") + "\"" + key + "\"";
    const std::string temperature = p.get_string("temperaturename", "temperature", diag);
    const std::vector<std::string> grids = vdb_grid_names(files.resolve(filename));
    if (std::find(grids.begin(), grids.end(), temperature) != grids.end() || !lost.empty())
        diag.warn(s.where, "nanovdb temperature",
                  what + ": the blackbody emission of a \"" + excerpt(temperature) + "\" grid is not imported (it does not emit)" +
                      (lost.empty() ? "" : "; ignored: " + lost));
}

}  // namespace

std::optional<json> translate_medium(const Statement& s, const std::string& name, const glm::dmat4& ctm,
                                     MaterialTranslator& materials, const FileNames& files, Diagnostics& diag) {
    const ParamList& p = s.params;
    const std::string type = p.get_string("type", "", diag);
    const std::string what = "MakeNamedMedium \"" + excerpt(name) + "\"";
    if (type != "homogeneous" && type != "uniformgrid" && type != "nanovdb") {
        for (const Param& q : p.params) q.used = true;
        diag.warn(s.where, "medium " + type,
                  what + ": medium type \"" + excerpt(type) + "\" is not supported (known: homogeneous, uniformgrid, nanovdb); "
                  "where it is named there is vacuum");
        return std::nullopt;
    }
    json m;
    m["type"] = type == "homogeneous" ? "homogeneous" : type == "uniformgrid" ? "grid" : "vdb";
    // pbrt-v4's defaults: HomogeneousMedium::Create's and GridMedium::Create's alike, and
    // NanoVDBMedium::Create's 1.
    const bool vdb = type == "nanovdb";
    const auto coefficient = [&](const char* key, const glm::dvec3& fallback) {
        json c = materials.colour(p, key, fallback, false, what);
        if (!c.is_array()) {
            diag.warn(s.where, "medium texture", what + ": a texture for \"" + key + "\" is not supported (pbrt-v4's default used)");
            c = rgb_json(fallback);
        }
        m[key] = c;
    };
    if (p.has("preset")) {
        diag.warn(s.where, "medium preset", what + ": \"preset\" \"" + excerpt(p.get_string("preset", "", diag)) +
                                                "\" (measured media) is not supported (sigma_a and sigma_s as given, or pbrt-v4's defaults)");
    }
    coefficient("sigma_a", vdb ? glm::dvec3(1.0) : glm::dvec3(0.0011, 0.0024, 0.014));
    coefficient("sigma_s", vdb ? glm::dvec3(1.0) : glm::dvec3(2.55, 3.21, 3.77));
    // Checked here, at the statement's line, rather than by the JSON loader at a key of the
    // converted document the user never wrote.
    for (const char* key : {"sigma_a", "sigma_s"})
        for (const json& c : m[key])
            if (!(c.get<double>() >= 0.0)) diag.fail(s.where, what + ": \"" + key + "\" must be >= 0 in every channel");
    const double scale = p.get_float("scale", 1.0, diag), g = p.get_float("g", 0.0, diag);
    if (!(scale >= 0.0)) diag.fail(s.where, what + ": \"scale\" must be >= 0");
    if (!(std::abs(g) < 1.0)) diag.fail(s.where, what + ": \"g\" must be in (-1, 1) (Henyey-Greenstein's asymmetry)");
    m["scale"] = scale;
    m["g"] = g;
    if (type == "homogeneous") {
        if (p.has("Le")) {
            const glm::dvec3 le = materials.emitted(p, "Le", what) * p.get_float("Lescale", 1.0, diag);
            m["emission"] = {le.r, le.g, le.b};
        }
        p.warn_unused(what, diag);
        return m;
    }
    if (vdb) {
        write_nanovdb(m, s, what, files, diag);
        write_transform(m, s, what, ctm, diag);
        p.warn_unused(what, diag);
        return m;
    }
    // A grid's blackbody emission from a "temperature" grid has no RGB counterpart here; "Le"
    // with its optional per-voxel "Lescale" (pbrt-v4's LeScale grid, read like the density:
    // trilinear, 0 outside the samples) is the scene's emission and emission_scale.
    if (p.has("temperature")) {
        for (const char* key : {"Le", "Lescale", "temperature", "temperaturescale", "temperatureoffset", "temperaturecutoff"})
            if (p.has(key)) p.find(key);
        diag.warn(s.where, "grid medium emission", what + ": a grid's blackbody emission from \"temperature\" is not imported (it does not emit)");
    }
    const std::vector<double> density = p.get_floats("density", diag);
    if (density.empty()) diag.fail(s.where, what + ": a \"uniformgrid\" needs \"float density\" values");
    charge_load_memory(density.size() * sizeof(json), s.where.text(), what + "'s density grid");
    const long long nx = p.get_int("nx", 1, diag), ny = p.get_int("ny", 1, diag), nz = p.get_int("nz", 1, diag);
    if (nx < 1 || ny < 1 || nz < 1 || static_cast<double>(nx) * static_cast<double>(ny) * static_cast<double>(nz) != static_cast<double>(density.size()))
        diag.fail(s.where, what + ": " + std::to_string(density.size()) + " \"density\" values, but nx x ny x nz = " +
                               std::to_string(nx) + " x " + std::to_string(ny) + " x " + std::to_string(nz));
    m["size"] = {nx, ny, nz};
    m["density"] = density;
    if (!p.has("temperature") && p.has("Le")) {
        const glm::dvec3 le = materials.emitted(p, "Le", what);
        const std::vector<double> le_scale = p.get_floats("Lescale", diag);
        if (!le_scale.empty() && le_scale.size() != density.size())
            diag.fail(s.where, what + ": " + std::to_string(le_scale.size()) + " \"Lescale\" values, but the grid has " +
                                   std::to_string(density.size()) + " (nx x ny x nz)");
        for (const double v : le_scale)
            if (!(v >= 0.0 && std::isfinite(v))) diag.fail(s.where, what + ": \"Lescale\" must be >= 0 and finite in every voxel");
        m["emission"] = {le.r, le.g, le.b};
        if (!le_scale.empty()) {
            charge_load_memory(le_scale.size() * sizeof(json), s.where.text(), what + "'s Lescale grid");
            m["emission_scale"] = le_scale;
        }
    }
    if (const auto p0 = p.get_point3("p0", diag)) m["p0"] = {p0->x, p0->y, p0->z};
    if (const auto p1 = p.get_point3("p1", diag)) m["p1"] = {p1->x, p1->y, p1->z};
    write_transform(m, s, what, ctm, diag);
    p.warn_unused(what, diag);
    return m;
}

}  // namespace sweeptrace::pbrt
