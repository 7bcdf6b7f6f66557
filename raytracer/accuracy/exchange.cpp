#include "raytracer/accuracy/exchange.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "raytracer/accuracy/reference.hpp"
#include "raytracer/accuracy/report.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace::accuracy {
namespace {

using nlohmann::json;
using namespace collision;

json vec(const glm::vec3& v) { return json::array({v.x, v.y, v.z}); }

json shape_json(const Sphere& s) { return {{"center", vec(s.center)}, {"radius", s.radius}}; }
json shape_json(const Aabb& s) { return {{"center", vec(s.center)}, {"size", vec(s.size)}}; }
json shape_json(const Cylinder& s) { return {{"center", vec(s.center)}, {"radius", s.radius}, {"height", s.height}}; }
json shape_json(const Capsule& s) { return {{"center", vec(s.center)}, {"radius", s.radius}, {"height", s.height}}; }
json shape_json(const OrientedCapsule& s) { return {{"a", vec(s.a)}, {"b", vec(s.b)}, {"radius", s.radius}}; }
json shape_json(const Ellipsoid& s) { return {{"center", vec(s.center)}, {"radii", vec(s.radii)}}; }
json shape_json(const Plane& s) { return {{"point", vec(s.point)}, {"normal", vec(s.normal)}}; }
json shape_json(const Disk& s) { return {{"center", vec(s.center)}, {"normal", vec(s.normal)}, {"radius", s.radius}}; }
json shape_json(const Quad& s) { return {{"corner", vec(s.corner)}, {"edge_u", vec(s.edge_u)}, {"edge_v", vec(s.edge_v)}}; }
json shape_json(const Triangle& s) { return {{"a", vec(s.a)}, {"b", vec(s.b)}, {"c", vec(s.c)}}; }

template <class F>
void for_each_shape(F&& f) {
    f(Sphere{});
    f(Aabb{});
    f(Cylinder{});
    f(Capsule{});
    f(OrientedCapsule{});
    f(Ellipsoid{});
    f(Plane{});
    f(Disk{});
    f(Quad{});
    f(Triangle{});
}

template <class S>
bool exported(Family f) {
    if (!family_applies<S>(f) || f == Family::SurfaceIn || f == Family::SurfaceOut) return false;
    return !(f == Family::Edges && (std::is_same_v<S, Triangle> || std::is_same_v<S, Quad>));
}

bool selected(const std::vector<std::string>& shapes, const std::string& name) {
    return shapes.empty() || std::find(shapes.begin(), shapes.end(), name) != shapes.end();
}

std::string outcome_name(RefOutcome o) { return o == RefOutcome::Hit ? "hit" : o == RefOutcome::Miss ? "miss" : "boundary"; }

template <class S>
std::size_t write_family(const std::filesystem::path& file, Family f, std::size_t n, std::uint64_t seed) {
    const std::vector<Case<S>> cases = make_cases<S>(f, n, seed);
    const std::string prefix = std::string(shape_name<S>()) + "/" + family_name(f) + "/";
    save_file(file, [&](std::ostream& out) {
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const Case<S>& c = cases[i];
            const RefHit ref = reference(c.ray, c.shape);
            const bool rounding = reference(c.ray, c.shape, float_band).outcome == RefOutcome::Boundary;
            json line{{"case", prefix + std::to_string(i)},
                      {"shape", shape_json(c.shape)},
                      {"ray", {{"origin", vec(c.ray.origin)}, {"dir", vec(c.ray.dir)}, {"tmin", c.ray.tmin}, {"tmax", c.ray.tmax}}},
                      {"reference", {{"outcome", outcome_name(ref.outcome)}, {"within_rounding", rounding}}}};
            if (ref.outcome == RefOutcome::Hit) line["reference"]["t"] = static_cast<double>(ref.t);
            out << line.dump() << '\n';
        }
    });
    return cases.size();
}

struct Answer {
    Result result;
    bool has_point = false;
    glm::vec3 point{0.0f};
};

struct Parsed {
    std::map<std::string, std::map<std::size_t, Answer>> groups;  // "shape/family" -> index -> answer
};

Parsed parse_results(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) throw InputError("cannot read results '" + path.string() + "'");
    Parsed p;
    std::string text;
    for (int line = 1; std::getline(in, text); ++line) {
        if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
        const std::string where = path.string() + ":" + std::to_string(line) + ": ";
        json j;
        try {
            j = json::parse(text);
        } catch (const std::exception& e) {
            throw InputError(where + "not JSON (" + e.what() + ")");
        }
        if (!j.is_object() || !j.contains("case") || !j["case"].is_string() || !j.contains("hit") || !j["hit"].is_boolean())
            throw InputError(where + "needs \"case\" (string) and \"hit\" (true/false)");
        const std::string id = j["case"];
        const std::size_t slash = id.rfind('/');
        if (slash == std::string::npos) throw InputError(where + "case '" + id + "' is not shape/family/index");
        Answer a;
        Result& r = a.result;
        r.hit = j["hit"];
        if (r.hit && !(j.contains("t") && j["t"].is_number())) throw InputError(where + "a hit needs \"t\" (number)");
        if (r.hit) r.h.t = j["t"].get<float>();
        if (r.hit && j.contains("point")) {
            const json& pt = j["point"];
            if (!pt.is_array() || pt.size() != 3 || !pt[0].is_number() || !pt[1].is_number() || !pt[2].is_number())
                throw InputError(where + "\"point\" must be [x, y, z]");
            a.has_point = true;
            a.point = {pt[0].get<float>(), pt[1].get<float>(), pt[2].get<float>()};
        }
        std::size_t index = 0;
        try {
            index = std::stoul(id.substr(slash + 1));
        } catch (const std::exception&) {
            throw InputError(where + "case '" + id + "' does not end in an index");
        }
        if (!p.groups[id.substr(0, slash)].emplace(index, a).second) throw InputError(where + "case '" + id + "' given twice");
    }
    return p;
}

template <class S>
void score_points(const std::vector<Case<S>>& cases, const std::map<std::size_t, Answer>& answers, PointErrors& row) {
    std::vector<double> errors;
    for (const auto& [i, a] : answers) {
        if (!a.has_point) continue;
        const RefHit ref = reference(cases[i].ray, cases[i].shape);
        if (ref.outcome != RefOutcome::Hit) continue;
        const LVec3 d = widen(cases[i].ray.dir), p_ref = widen(cases[i].ray.origin) + ref.t * d;
        const LVec3 e = widen(a.point) - p_ref;
        const long double travelled = ref.t * std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        errors.push_back(static_cast<double>(std::sqrt(e.x * e.x + e.y * e.y + e.z * e.z) / travelled));
    }
    row.scored = errors.size();
    if (errors.empty()) return;
    std::sort(errors.begin(), errors.end());
    row.median = errors[errors.size() / 2];
    row.p99 = errors[std::min(errors.size() - 1, static_cast<std::size_t>(0.99 * double(errors.size())))];
    row.max = errors.back();
}

template <class S>
void score_shape(const Parsed& p, const std::filesystem::path& path, std::size_t n, std::uint64_t seed,
                 const std::string& variant, std::vector<Metrics>& rows, std::vector<PointErrors>* points) {
    for (Family f : all_families) {
        const auto it = p.groups.find(std::string(shape_name<S>()) + "/" + family_name(f));
        if (it == p.groups.end()) continue;
        if (!exported<S>(f)) throw InputError(path.string() + ": " + it->first + " is not an exported family");
        const std::vector<Case<S>> cases = make_cases<S>(f, n, seed);
        if (it->second.size() != cases.size() || it->second.rbegin()->first >= cases.size())
            throw InputError(path.string() + ": " + it->first + " has " + std::to_string(it->second.size()) +
                             " results for " + std::to_string(cases.size()) + " cases (score with the --rays and --seed "
                             "of the export)");
        std::vector<S> shapes;
        std::vector<Ray> rays;
        std::vector<Result> results;
        for (std::size_t i = 0; i < cases.size(); ++i) {
            shapes.push_back(cases[i].shape);
            rays.push_back(cases[i].ray);
            results.push_back(it->second.at(i).result);
        }
        if (points) {
            PointErrors pe{shape_name<S>(), family_name(f)};
            score_points(cases, it->second, pe);
            if (pe.scored > 0) points->push_back(pe);
        }
        Metrics m = score(shapes, rays, results);
        if (f == Family::Edges) m.leaks = m.wrong - m.false_hits;  // as run_cases: rays start inside
        m.shape = shape_name<S>();
        m.variant = variant;
        m.family = family_name(f);
        rows.push_back(m);
    }
}

}  // namespace

void export_rays(const std::filesystem::path& dir, const std::vector<std::string>& shapes, std::size_t n,
                 std::uint64_t seed) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw InputError("cannot create '" + dir.string() + "': " + ec.message());
    json manifest{{"format", "sweeptrace accuracy rays, version 1"}, {"rays_per_family", n}, {"seed", seed},
                  {"files", json::array()}};
    for_each_shape([&](auto tag) {
        using S = decltype(tag);
        if (!selected(shapes, shape_name<S>())) return;
        for (Family f : all_families) {
            if (!exported<S>(f)) continue;
            const std::string file = std::string(shape_name<S>()) + "-" + family_name(f) + ".jsonl";
            const std::size_t count = write_family<S>(dir / file, f, n, seed);
            manifest["files"].push_back({{"shape", shape_name<S>()}, {"family", family_name(f)}, {"file", file}, {"cases", count}});
        }
    });
    save_file(dir / "manifest.json", [&](std::ostream& out) { out << manifest.dump(2) << '\n'; });
}

std::vector<Metrics> score_results(const std::filesystem::path& results, std::size_t n, std::uint64_t seed,
                                   const std::string& variant, std::vector<PointErrors>* points) {
    const Parsed p = parse_results(results);
    std::vector<Metrics> rows;
    std::size_t known = 0;
    for_each_shape([&](auto tag) {
        using S = decltype(tag);
        for (Family f : all_families) known += p.groups.count(std::string(shape_name<S>()) + "/" + family_name(f));
        score_shape<S>(p, results, n, seed, variant, rows, points);
    });
    if (known != p.groups.size())
        for (const auto& [group, unused] : p.groups) {
            (void)unused;
            bool found = false;
            for (const Metrics& m : rows) found |= m.shape + "/" + m.family == group;
            if (!found) throw InputError(results.string() + ": unknown shape/family '" + group + "'");
        }
    if (rows.empty()) throw InputError(results.string() + ": no results");
    return rows;
}

void write_point_errors(std::ostream& out, const std::vector<PointErrors>& rows) {
    if (rows.empty()) return;
    out << "\n| shape | family | points scored | point rel. err. median | p99 | max |\n|---|---|---:|---:|---:|---:|\n";
    char buf[160];
    for (const PointErrors& r : rows) {
        std::snprintf(buf, sizeof buf, "| %s | %s | %zu | %.3g | %.3g | %.3g |\n", r.shape.c_str(), r.family.c_str(), r.scored,
                      r.median, r.p99, r.max);
        out << buf;
    }
    out << "(point error: |p - p_ref| / (t_ref |dir|), where both hit)\n";
}

}  // namespace sweeptrace::accuracy
