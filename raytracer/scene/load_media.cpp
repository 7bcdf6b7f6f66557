#include "raytracer/scene/load_media.hpp"

#include <cmath>
#include <vector>

#include <glm/matrix.hpp>

#include "raytracer/input_error.hpp"
#include "raytracer/load_budget.hpp"
#include "raytracer/scene/vdb_grid.hpp"

namespace sweeptrace {

namespace {

using scene_json::Node;

// sigma (>= 0 per channel) times scale, finite.
glm::vec3 read_sigma(const Node& medium, std::string_view key, float scale) {
    const std::optional<Node> n = medium.find(key);
    if (!n) return glm::vec3(0.0f);
    const glm::vec3 v = n->vec3_at_least(0.0f) * scale;
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        n->fail("times the medium's scale " + scene_json::format_number(scale) + " is not a finite number");
    return v;
}

// nx ny nz numbers >= 0, charged to the load budget before they are copied.
std::vector<float> read_grid_values(const Node& node, std::size_t count, const std::string& what) {
    const std::size_t n = node.array_size();
    if (n != count)
        node.fail("must hold size[0] x size[1] x size[2] = " + std::to_string(count) + " numbers, got " + std::to_string(n));
    charge_load_memory(count * sizeof(float), node.file().string(), what);
    std::vector<float> values(count);
    for (std::size_t i = 0; i < count; ++i) {
        const auto& v = node.value()[i];
        const double d = v.is_number() ? v.get<double>() : -1.0;
        values[i] = static_cast<float>(d);
        // Not a number, negative, or not finite once a float: the reader's placed message.
        if (!(d >= 0.0) || !std::isfinite(values[i])) node.element(i).number_at_least(0.0f, true);
    }
    return values;
}

// A "vdb" medium's density: the file's grid as the dense grid a "grid" medium renders
// (vdb_grid.hpp), its index-to-world map composed after the medium's own transform.
void read_vdb_grid(const Node& node, Medium& m, Transform (*read_transform)(const Node&)) {
    const Node file = node.at("file");
    const std::string relative = file.string();
    if (relative.empty()) file.fail("must name an OpenVDB (.vdb) or NanoVDB (.nvdb) file");
    const std::string grid = node.has("grid") ? node.at("grid").string() : "density";
    VdbDensity v;
    try {
        v = read_vdb_density(node.file().parent_path() / relative, grid, "medium \"" + excerpt(m.name) + "\"");
    } catch (const InputError& e) {
        file.fail(e.what());
    }
    const double det = glm::determinant(v.index_to_world);
    if (!(det != 0.0) || !std::isfinite(det))
        file.fail("grid \"" + excerpt(grid) + "\"'s index-to-world transform is singular or not finite");
    glm::dmat4 to_medium(1.0);
    if (auto t = node.find("transform")) to_medium = glm::dmat4(read_transform(*t).to_object);
    m.to_medium = glm::mat4(glm::inverse(v.index_to_world) * to_medium);
    m.nx = v.nx;
    m.ny = v.ny;
    m.nz = v.nz;
    m.density = std::move(v.density);
    m.p0 = v.p0;
    m.p1 = v.p1;
}

Medium read_medium(const Node& node, const std::string& name, Transform (*read_transform)(const Node&)) {
    if (!node.value().is_object()) node.fail("must be an object with a \"type\"");
    const Node type_node = node.at("type");
    const std::string type = type_node.string();
    Medium m;
    m.name = name;
    if (type == "homogeneous") {
        node.require_object({"type", "sigma_a", "sigma_s", "scale", "g", "emission"});
    } else if (type == "grid") {
        node.require_object({"type", "sigma_a", "sigma_s", "scale", "g", "emission", "size", "density", "p0", "p1",
                             "transform", "emission_scale"});
        m.kind = Medium::Kind::Grid;
    } else if (type == "vdb") {
        node.require_object({"type", "sigma_a", "sigma_s", "scale", "g", "emission", "file", "grid", "transform"});
        m.kind = Medium::Kind::Grid;
    } else {
        type_node.fail("unknown medium type \"" + type + "\" (known: homogeneous, grid, vdb)");
    }
    const float scale = node.has("scale") ? node.at("scale").number_at_least(0.0f, true) : 1.0f;
    m.sigma_a = read_sigma(node, "sigma_a", scale);
    m.sigma_s = read_sigma(node, "sigma_s", scale);
    if (auto g = node.find("g")) {
        m.g = g->number();
        if (!(std::abs(m.g) < 1.0f)) g->fail("must be in (-1, 1) (Henyey-Greenstein's asymmetry; +-1 is a delta), got " + g->shown());
    }
    if (auto e = node.find("emission")) m.emission = e->vec3_at_least(0.0f);
    if (m.kind == Medium::Kind::Homogeneous) return m;
    if (type == "vdb") {
        read_vdb_grid(node, m, read_transform);
        return m;
    }

    const Node size = node.at("size");
    if (size.array_size() != 3) size.fail("must be [nx, ny, nz], three positive integers");
    // Each axis fits an int; the product is bounded by the density array's real length below.
    int* dims[3] = {&m.nx, &m.ny, &m.nz};
    for (std::size_t a = 0; a < 3; ++a) *dims[a] = static_cast<int>(size.element(a).integer(1, 1 << 24));
    const std::size_t count = static_cast<std::size_t>(m.nx) * static_cast<std::size_t>(m.ny) * static_cast<std::size_t>(m.nz);
    m.density = read_grid_values(node.at("density"), count, "medium \"" + name + "\"'s density grid");
    if (auto es = node.find("emission_scale")) {
        if (!node.has("emission")) es->fail("scales the medium's \"emission\", which is not given");
        m.emission_scale = read_grid_values(*es, count, "medium \"" + name + "\"'s emission_scale grid");
    }
    if (auto p0 = node.find("p0")) m.p0 = p0->vec3();
    if (auto p1 = node.find("p1")) m.p1 = p1->vec3();
    for (int a = 0; a < 3; ++a)
        if (!(m.p1[a] > m.p0[a]) || !std::isfinite(m.p1[a] - m.p0[a]))
            (node.has("p1") ? node.at("p1") : node).fail("must be above p0 on every axis (the grid's box is [p0, p1]), got p0 " +
                                                         scene_json::format_number(m.p0[a]) + " and p1 " +
                                                         scene_json::format_number(m.p1[a]) + " on axis " + "xyz"[a]);
    if (auto t = node.find("transform")) m.to_medium = read_transform(*t).to_object;
    return m;
}

}  // namespace

MediumIndex read_media(const Node& media, Scene& scene, Transform (*read_transform)(const Node&)) {
    if (!media.value().is_object())
        media.fail("must be an object mapping names to media, got " + scene_json::describe_type(media.value()));
    MediumIndex index;
    for (const auto& item : media.value().items()) {
        const Node m = media.at(item.key());
        if (item.key().empty()) m.fail("a medium name must not be empty");
        index[item.key()] = static_cast<std::int32_t>(scene.media.size());
        scene.media.push_back(read_medium(m, item.key(), read_transform));
    }
    return index;
}

std::int32_t read_medium_name(const Node& name, const MediumIndex& media) {
    const std::string s = name.string();
    const auto it = media.find(s);
    if (it == media.end()) {
        std::string known;
        for (const auto& [n, i] : media) known += (known.empty() ? "" : ", ") + n;
        name.fail("unknown medium \"" + s + "\" (defined in \"media\": " + (known.empty() ? "none" : known) + ")");
    }
    return it->second;
}

MediumInterface read_medium_interface(const Node& object, const MediumIndex& media) {
    MediumInterface mi;
    if (auto in = object.find("inside")) mi.inside = read_medium_name(*in, media);
    if (auto out = object.find("outside")) mi.outside = read_medium_name(*out, media);
    return mi;
}

}  // namespace sweeptrace
