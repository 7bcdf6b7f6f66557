// pbrt-v4 shapes as our objects (scenes/README.md "Objects"). Analytic shapes stay analytic, in
// the object space pbrt defines them in: a sphere about the origin, a disk in the plane
// z = "height", a cylinder about the z axis (ours is about y: turned by 90 degrees about x).
// Triangle and bilinear meshes given inline become inline mesh objects, their vertices
// transformed to the world here, with their normals and uv; a plymesh becomes a mesh object
// naming its file.
//
// Which side emits: pbrt's triangle normal is (p1 - p0) x (p2 - p0) (for p0 p1 p2 as indexed),
// ours (b - a) x (c - a) for a b c: the same vertex order gives the same side. pbrt turns the
// normal over under ReverseOrientation and under a transform that swaps handedness (and, with
// "N", toward the interpolated normal); each turn here swaps b and c. A bilinear patch
// p00 p10 p01 p11 faces (p10 - p00) x (p01 - p00) and splits into (p00 p10 p11) and
// (p00 p11 p01), which face the same way.
#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "raytracer/input_error.hpp"
#include "raytracer/scene/pbrt/pbrt_transform.hpp"
#include "raytracer/scene/pbrt/pbrt_world.hpp"
#include "raytracer/scene/scene_transform.hpp"

namespace sweeptrace::pbrt {

using nlohmann::json;

namespace {


glm::dmat4 object_mirror_x() {
    glm::dmat4 m(1.0);
    m[0][0] = -1.0;
    return m;
}

bool reads_texture(const json& material) {
    for (const auto& item : material.items())
        if (item.value().is_object()) return true;
    return false;
}

std::vector<glm::dvec3> points(const std::vector<double>& v) {
    std::vector<glm::dvec3> out(v.size() / 3);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
    return out;
}

// trianglemesh (corners 3) and bilinearmesh (corners 4), checked like pbrt does, as one inline
// mesh object (scene/inline_mesh.hpp) in world space: pbrt's vertex normals "N" (to the world by
// the inverse transpose, turned over under ReverseOrientation as pbrt-v4 does) and "uv" are kept.
// Without "uv" pbrt gives each triangle (0, 0), (1, 0), (1, 1) and each patch (0, 0), (1, 0),
// (0, 1), (1, 1) at p00 p10 p01 p11; a textured material then gets those, its faces' vertices
// unshared.
void write_mesh(WorldContext& w, const ShapeRecord& s, int corners) {
    const ParamList& p = s.statement.params;
    Diagnostics& d = w.diag;
    const std::string what = "Shape \"" + s.statement.type + "\"";
    const std::vector<glm::dvec3> pts = points(p.get_floats("P", d));
    std::vector<long long> idx = p.get_ints("indices", d);
    const std::vector<glm::dvec3> normals = points(p.get_floats("N", d));
    if (pts.empty()) d.fail(s.statement.where, what + ": needs \"point3 P\" (the vertices)");
    if (p.has("P") && p.find("P")->type != "point3") d.fail(s.statement.where, what + ": \"P\" must be point3");
    if (idx.empty()) {
        if (pts.size() != static_cast<std::size_t>(corners))
            d.fail(s.statement.where, what + ": needs \"integer indices\" (only a mesh of exactly " + std::to_string(corners) + " vertices may leave them out)");
        for (int i = 0; i < corners; ++i) idx.push_back(i);
    }
    if (idx.size() % static_cast<std::size_t>(corners) != 0)
        d.fail(s.statement.where, what + ": \"indices\" must be a multiple of " + std::to_string(corners) + ", got " + std::to_string(idx.size()));
    for (long long i : idx)
        if (i < 0 || static_cast<std::size_t>(i) >= pts.size())
            d.fail(s.statement.where, what + ": index " + std::to_string(i) + " out of range (the mesh has " + std::to_string(pts.size()) + " vertices in \"P\")");
    if (!normals.empty() && normals.size() != pts.size())
        d.fail(s.statement.where, what + ": \"N\" must give one normal per vertex of \"P\" (" + std::to_string(normals.size()) + " for " + std::to_string(pts.size()) + ")");
    const std::vector<double> uv = p.get_floats("uv", d);
    if (!uv.empty() && uv.size() != 2 * pts.size())
        d.fail(s.statement.where, what + ": \"uv\" must give one (u, v) per vertex of \"P\"");
    p.find("S");
    p.find("faceIndices");
    const glm::dmat4& m = s.ctm;
    // As our loader will see them: rounded to float.
    std::vector<glm::dvec3> world(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) world[i] = glm::dvec3(glm::vec3(m * glm::dvec4(pts[i], 1.0)));
    double area = 0.0;  // for an area light's "power"
    for (std::size_t f = 0; f < idx.size(); f += static_cast<std::size_t>(corners)) {
        const glm::dvec3& a = world[idx[f]];
        area += 0.5 * glm::length(glm::cross(world[idx[f + 1]] - a, world[idx[f + 2]] - a));
        if (corners == 4) area += 0.5 * glm::length(glm::cross(world[idx[f + 2]] - world[idx[f + 3]], world[idx[f + 1]] - world[idx[f + 3]]));
    }
    const std::optional<std::string> material = w.material_for(s, area);
    if (!material) return;
    const bool default_uv = uv.empty() && reads_texture(w.doc["materials"][*material]);

    // Vertex normals in the world; a normal without direction drops them all (flat shading), as
    // our loader refuses one.
    std::vector<glm::dvec3> world_normals;
    if (!normals.empty()) {
        const glm::dmat3 normal_m = glm::transpose(glm::inverse(glm::dmat3(m)));
        for (const glm::dvec3& n : normals) {
            const glm::dvec3 t = normal_m * n;
            const double len = glm::length(glm::dvec3(glm::vec3(t)));
            if (!(len > 0.0) || !std::isfinite(len)) {
                d.warn(s.statement.where, "zero mesh normal", what + ": a vertex normal \"N\" of zero length: the mesh is flat shaded");
                world_normals.clear();
                break;
            }
            world_normals.push_back((s.reverse_orientation ? -1.0 : 1.0) * t / len);
        }
    }

    // Each triangle's corners (into `world`) and, without "uv", pbrt's default uv at each corner.
    struct Corner {
        long long v;
        glm::dvec2 uv;
    };
    std::vector<std::array<Corner, 3>> tris;
    bool non_planar = false;
    for (std::size_t f = 0; f < idx.size(); f += static_cast<std::size_t>(corners)) {
        const long long i0 = idx[f], i1 = idx[f + 1], i2 = idx[f + 2];
        if (corners == 3) {
            tris.push_back({Corner{i0, {0, 0}}, Corner{i1, {1, 0}}, Corner{i2, {1, 1}}});
        } else {
            const long long i3 = idx[f + 3];  // p00 p10 p01 p11 = i0 i1 i2 i3
            const glm::dvec3 e = world[i3] - (world[i1] + world[i2] - world[i0]);
            non_planar |= glm::length(e) > 1e-6 * (glm::length(world[i1] - world[i0]) + glm::length(world[i2] - world[i0]));
            tris.push_back({Corner{i0, {0, 0}}, Corner{i1, {1, 0}}, Corner{i3, {1, 1}}});
            tris.push_back({Corner{i0, {0, 0}}, Corner{i3, {1, 1}}, Corner{i2, {0, 1}}});
        }
    }

    // The front: pbrt's (p1 - p0) x (p2 - p0) is ours for the same order, turned over under
    // ReverseOrientation and a handedness swap; with "N" the side the normals are on (pbrt faces
    // the geometric normal toward the shading one).
    const bool flip = s.reverse_orientation != (det3(s.ctm) < 0.0);
    json vertices = json::array(), indices = json::array(), uvs = json::array(), out_normals = json::array();
    auto put = [](json& a, std::initializer_list<double> values) {
        for (double x : values) a.push_back(x);
    };
    if (!default_uv) {
        for (const glm::dvec3& v : world) put(vertices, {v.x, v.y, v.z});
        for (const glm::dvec3& n : world_normals) put(out_normals, {n.x, n.y, n.z});
        for (double x : uv) uvs.push_back(x);
    }
    std::size_t kept = 0, degenerate = 0;
    for (const auto& t : tris) {
        const glm::dvec3 n = glm::cross(world[t[1].v] - world[t[0].v], world[t[2].v] - world[t[0].v]);
        if (n == glm::dvec3(0.0)) {
            ++degenerate;
            continue;
        }
        bool swap = flip;
        if (!world_normals.empty()) swap = glm::dot(n, world_normals[t[0].v] + world_normals[t[1].v] + world_normals[t[2].v]) < 0.0;
        const std::array<Corner, 3> c{t[0], swap ? t[2] : t[1], swap ? t[1] : t[2]};
        for (const Corner& k : c) {
            if (!default_uv) {
                indices.push_back(k.v);
                continue;
            }
            indices.push_back(vertices.size() / 3);
            put(vertices, {world[k.v].x, world[k.v].y, world[k.v].z});
            put(uvs, {k.uv.x, k.uv.y});
            if (!world_normals.empty()) put(out_normals, {world_normals[k.v].x, world_normals[k.v].y, world_normals[k.v].z});
        }
        ++kept;
    }
    if (degenerate > 0) d.warn(s.statement.where, "degenerate triangle", what + ": triangles without area are left out");
    if (non_planar) d.warn(s.statement.where, "curved bilinear patch", what + ": a non-planar patch is approximated by two triangles");
    if (kept == 0) return;
    w.triangles += kept;
    if (w.triangles > kMaxInlineTriangles)
        d.fail(s.statement.where, "more than " + std::to_string(kMaxInlineTriangles) +
                                      " triangles given inline (trianglemesh, bilinearmesh) in all: write large meshes as PLY files (Shape \"plymesh\")");
    json object{{"type", "mesh"}, {"vertices", std::move(vertices)}, {"indices", std::move(indices)}};
    if (!out_normals.empty()) object["normals"] = std::move(out_normals);
    if (!uvs.empty()) object["uvs"] = std::move(uvs);
    object["material"] = *material;
    w.doc["objects"].push_back(std::move(object));
}

// A sphere, disk or cylinder: the transform to the world, mirrored back in the shape's own x
// (which the shape is symmetric in) when it would mirror. `emits_flipped` says whether pbrt's
// emitting side is the inside / the -z side.
void write_analytic(WorldContext& w, const ShapeRecord& s, json object, const glm::dmat4& object_to_pbrt, double area) {
    glm::dmat4 m = s.ctm;
    if (det3(m) < 0.0) m = m * object_mirror_x();
    m = m * object_to_pbrt;
    const std::optional<std::string> material = w.material_for(s, area);
    if (!material) return;
    const std::optional<json> steps = transform_json(m);
    if (!steps) w.diag.fail(s.statement.where, "Shape \"" + s.statement.type + "\": its transform is singular (a zero scale?)");
    object["material"] = *material;
    if (!steps->empty()) object["transform"] = *steps;
    w.doc["objects"].push_back(std::move(object));
}

// The area scale of a transform for a surface: exact for similarities, approximated otherwise.
double area_scale(const ShapeRecord& s) {
    const std::optional<AffineSteps> a = split_affine(s.ctm * (det3(s.ctm) < 0 ? object_mirror_x() : glm::dmat4(1.0)));
    if (!a) return 1.0;
    const glm::dvec3 k = a->scale;
    return std::cbrt(k.x * k.y * k.z) * std::cbrt(k.x * k.y * k.z);
}

void warn_partial(WorldContext& w, const ShapeRecord& s, bool partial, const std::string& instead) {
    if (partial)
        w.diag.warn(s.statement.where, "partial " + s.statement.type,
                    "Shape \"" + s.statement.type + "\": a partial shape (zmin/zmax/phimax/innerradius) is not supported: " + instead);
}

}  // namespace

void write_shape(WorldContext& w, const ShapeRecord& s) {
    const std::string& type = s.statement.type;
    const ParamList& p = s.statement.params;
    Diagnostics& d = w.diag;
    const std::string what = "Shape \"" + excerpt(type) + "\"";
    {
        std::string tex;
        const std::optional<double> alpha = p.get_float_or_texture("alpha", tex, d);
        if (alpha && (!tex.empty() || *alpha != 1.0))
            d.warn(s.statement.where, "alpha", what + ": \"alpha\" (cut-outs) is not supported (the shape is opaque)");
    }
    const bool emits_inward = s.area_light && (s.reverse_orientation != (det3(s.ctm) < 0.0));
    if (type == "sphere") {
        const double r = p.get_float("radius", 1.0, d);
        if (!(r > 0.0)) d.fail(s.statement.where, what + ": \"radius\" must be > 0");
        const double zmin = p.get_float("zmin", -r, d), zmax = p.get_float("zmax", r, d), phimax = p.get_float("phimax", 360.0, d);
        warn_partial(w, s, zmin > -r || zmax < r || phimax < 360.0, "a full sphere instead");
        if (emits_inward)
            d.warn(s.statement.where, "inward sphere light", what + ": a sphere light turned inside out (ReverseOrientation) emits outward here");
        write_analytic(w, s, {{"type", "sphere"}, {"radius", r}}, glm::dmat4(1.0), 4.0 * kPi * r * r * area_scale(s));
    } else if (type == "disk") {
        const double r = p.get_float("radius", 1.0, d), h = p.get_float("height", 0.0, d);
        if (!(r > 0.0)) d.fail(s.statement.where, what + ": \"radius\" must be > 0");
        const double inner = p.get_float("innerradius", 0.0, d), phimax = p.get_float("phimax", 360.0, d);
        warn_partial(w, s, inner > 0.0 || phimax < 360.0, "a full disk instead");
        // The disk faces +z in pbrt's object space; a mirroring CTM is undone in the object's x
        // (write_analytic), which keeps that side, so only pbrt's own turn applies.
        const double nz = emits_inward ? -1.0 : 1.0;
        write_analytic(w, s, {{"type", "disk"}, {"center", {0.0, 0.0, h}}, {"normal", {0.0, 0.0, nz}}, {"radius", r}}, glm::dmat4(1.0),
                       kPi * r * r * area_scale(s));
    } else if (type == "cylinder") {
        const double r = p.get_float("radius", 1.0, d);
        double zmin = p.get_float("zmin", -1.0, d), zmax = p.get_float("zmax", 1.0, d);
        const double phimax = p.get_float("phimax", 360.0, d);
        if (zmin > zmax) std::swap(zmin, zmax);
        if (!(r > 0.0) || !(zmax > zmin)) d.fail(s.statement.where, what + ": needs \"radius\" > 0 and zmin != zmax");
        warn_partial(w, s, phimax < 360.0, "a full cylinder instead");
        d.warn(s.statement.where, "open cylinder", what + ": pbrt's cylinder is open; ours is closed by flat caps (approximated)");
        // Our cylinder stands on y; pbrt's on z: a quarter turn about x takes y to z.
        write_analytic(w, s, {{"type", "cylinder"}, {"center", {0.0, 0.5 * (zmin + zmax), 0.0}}, {"radius", r}, {"height", zmax - zmin}},
                       rotation_matrix({1.0, 0.0, 0.0}, 90.0), 2.0 * kPi * r * (zmax - zmin) * area_scale(s));
    } else if (type == "trianglemesh") {
        write_mesh(w, s, 3);
    } else if (type == "bilinearmesh") {
        write_mesh(w, s, 4);
    } else if (type == "loopsubdiv") {
        d.warn(s.statement.where, "loopsubdiv", what + ": subdivision is not supported: its control mesh is drawn (approximated)");
        p.find("levels");
        write_mesh(w, s, 3);
    } else if (type == "plymesh") {
        const std::string file = p.get_string("filename", "", d);
        if (file.empty()) d.fail(s.statement.where, what + ": needs \"string filename\"");
        if (const std::string problem = file_kind_problem(w.files.resolve(file)); !problem.empty())
            d.fail(s.statement.where, what + ": \"" + excerpt(file) + "\" " + problem + " (looked for " + w.files.resolve(file).string() + ")");
        if (p.has("displacement")) {
            p.find("displacement");
            d.warn(s.statement.where, "displacement", what + ": \"displacement\" is not supported (ignored)");
        }
        p.find("edgelength");
        // A mirroring CTM is written as a mirror in the mesh's own x first ({"scale": [-1, 1, 1]}, which
        // our mesh objects allow), then the rest, which keeps orientation. Each face's front is then
        // its file's, carried by the inverse transpose: pbrt's for a transform that swaps handedness.
        const bool mirrors = det3(s.ctm) < 0.0;
        const glm::dmat4 m = mirrors ? s.ctm * object_mirror_x() : s.ctm;
        if (s.area_light && s.reverse_orientation && !s.area_light->statement.params.get_bool("twosided", false, d))
            d.warn(s.statement.where, "reversed plymesh light", what + ": ReverseOrientation of an emitting mesh file is not applied (it emits from its faces' front)");
        const std::optional<std::string> material = w.material_for(s, 0.0);
        if (!material) return;
        if (s.area_light && s.area_light->statement.params.has("power"))
            d.warn(s.statement.where, "plymesh power", what + ": \"power\" of an emitting mesh file needs its area, which the converter does not read: the light's L is used");
        std::optional<json> steps = transform_json(m);
        if (!steps) d.fail(s.statement.where, what + ": its transform is singular (a zero scale?)");
        if (mirrors) steps->insert(steps->begin(), json{{"scale", {-1.0, 1.0, 1.0}}});
        json object{{"type", "mesh"}, {"file", w.files.json_path(file)}, {"material", *material}};
        if (!steps->empty()) object["transform"] = *steps;
        w.doc["objects"].push_back(std::move(object));
    } else {
        d.warn(s.statement.where, "shape " + type, "Shape \"" + excerpt(type) + "\" is not supported (ignored)");
        for (const Param& q : p.params) q.used = true;
        return;
    }
    p.warn_unused(what, d);
}

}  // namespace sweeptrace::pbrt
