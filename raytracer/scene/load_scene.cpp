#include "raytracer/scene/load_scene.hpp"
#include "raytracer/scene/load_scene_document.hpp"

#include <initializer_list>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <glm/geometric.hpp>

#include "raytracer/geometry/shape.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/load_budget.hpp"
#include "raytracer/scene/film_limits.hpp"
#include "raytracer/scene/gzip_file.hpp"
#include "raytracer/scene/inline_mesh.hpp"
#include "raytracer/scene/json_reader.hpp"
#include "raytracer/scene/load_film_display.hpp"
#include "raytracer/scene/load_environment.hpp"
#include "raytracer/scene/load_filter.hpp"
#include "raytracer/scene/load_lights.hpp"
#include "raytracer/scene/load_media.hpp"
#include "raytracer/scene/load_motion.hpp"
#include "raytracer/scene/load_portal.hpp"
#include "raytracer/scene/load_texture.hpp"
#include "raytracer/scene/named_metals.hpp"
#include "raytracer/scene/obj_materials.hpp"
#include "raytracer/scene/obj_loader.hpp"
#include "raytracer/scene/ply_loader.hpp"
#include "raytracer/scene/read_files.hpp"
#include "raytracer/scene/scene_extent.hpp"
#include "raytracer/scene/scene_transform.hpp"
#include "raytracer/scene/text_file.hpp"

namespace sweeptrace {

namespace {

using scene_json::Node;

using scene_keys::parallel;

Camera read_camera(const Node& node) {
    node.require_object({"position", "look_at", "up", "fov", "aperture", "focus_distance", "near_clip", "handedness", "shutter",
                         "medium"});
    Camera camera;
    camera.position = node.at("position").vec3();
    camera.look_at = node.at("look_at").vec3();
    if (camera.position == camera.look_at) node.at("look_at").fail("must differ from camera.position");
    if (auto up = node.find("up")) {
        camera.up = up->nonzero_vec3();
        if (parallel(camera.up, camera.look_at - camera.position))
            up->fail("must not be parallel to the viewing direction (look_at - position)");
    }
    if (auto fov = node.find("fov")) {
        camera.vfov_degrees = fov->number();
        if (!(camera.vfov_degrees > 0.0f && camera.vfov_degrees < 180.0f))
            fov->fail("must be a vertical field of view in degrees, strictly between 0 and 180, got " + fov->shown());
    }
    if (auto aperture = node.find("aperture")) camera.aperture = aperture->number_at_least(0.0f, true);
    if (auto focus = node.find("focus_distance")) camera.focus_distance = focus->number_at_least(0.0f, false);
    if (auto near = node.find("near_clip")) camera.near_clip = near->number_at_least(0.0f, true);
    if (auto hand = node.find("handedness")) {
        const std::string h = hand->string();
        if (h != "right" && h != "left") hand->fail("must be \"right\" (ours, the default) or \"left\" (pbrt's camera space), got " + hand->shown());
        camera.left_handed = h == "left";
    }
    if (auto shutter = node.find("shutter")) read_shutter(*shutter, camera);
    return camera;
}

// The same ranges as the command line's overrides (film_limits.hpp).
int read_film_setting(const Node& node, FilmSetting setting) {
    const SettingRange r = film_range(setting);
    return static_cast<int>(node.integer(r.lo, r.hi));
}

Film read_film(const Node& node) {
    node.require_object({"width", "height", "spp", "max_depth", "sampler", "guiding", "exposure", "tone_curve", "filter",
                         "clamp_indirect", "clamp_sample", "integrator", "vcm_radius", "aovs"});
    Film film;
    film.width = read_film_setting(node.at("width"), FilmSetting::Width);
    film.height = read_film_setting(node.at("height"), FilmSetting::Height);
    if (auto spp = node.find("spp")) film.spp = read_film_setting(*spp, FilmSetting::Spp);
    if (auto depth = node.find("max_depth")) film.max_depth = read_film_setting(*depth, FilmSetting::MaxDepth);
    if (auto sampler = node.find("sampler")) {
        const std::string name = sampler->string();
        if (name == "sobol") film.sampler = SamplerKind::Sobol;
        else if (name == "independent") film.sampler = SamplerKind::Independent;
        else sampler->fail("unknown sampler \"" + name + "\" (known: sobol, independent)");
    }
    if (auto guiding = node.find("guiding")) film.guiding = guiding->boolean();
    if (auto aovs = node.find("aovs")) film.aovs = aovs->boolean();
    if (auto integrator = node.find("integrator")) {
        const std::string name = integrator->string();
        if (name == "path") film.integrator = IntegratorKind::Path;
        else if (name == "bdpt") film.integrator = IntegratorKind::Bdpt;
        else if (name == "vcm") film.integrator = IntegratorKind::Vcm;
        else integrator->fail("unknown integrator \"" + name + "\" (known: path, bdpt, vcm)");
    }
    if (auto radius = node.find("vcm_radius")) film.vcm_radius = radius->number_in(vcm_radius_range().lo, vcm_radius_range().hi);
    if (auto clamp = node.find("clamp_indirect")) film.clamp_indirect = clamp->number_at_least(0.0f, false);
    if (auto clamp = node.find("clamp_sample")) film.clamp_sample = clamp->number_at_least(0.0f, false);
    read_film_display(node, film);
    if (auto f = node.find("filter")) film.filter = read_filter(*f);
    return film;
}

Background read_background(const Node& node) {
    node.require_object({"color", "sky", "environment", "portal"});
    Background background;
    const bool color = node.has("color"), sky = node.has("sky"), env = node.has("environment");
    if (int(color) + int(sky) + int(env) != 1) node.fail("give exactly one of \"color\", \"sky\" or \"environment\"");
    if (env) {
        read_environment(node.at("environment"), background);
    } else if (color) {
        background.kind = Background::Kind::Constant;
        background.color = node.at("color").vec3_at_least(0.0f);
    } else {
        const Node s = node.at("sky");
        s.require_object({"horizon", "zenith"});
        background.kind = Background::Kind::Sky;
        background.horizon = s.at("horizon").vec3_at_least(0.0f);
        background.zenith = s.at("zenith").vec3_at_least(0.0f);
    }
    if (auto portal = node.find("portal")) read_portal(*portal, background);
    return background;
}

glm::vec3 read_albedo(const Node& node) {
    const glm::vec3 v = node.vec3_at_least(0.0f);
    for (int i = 0; i < 3; ++i)
        if (v[i] > 1.0f) node.element(static_cast<std::size_t>(i)).number_in(0.0f, 1.0f);
    return v;
}

// A conductor's eta (> 0) or k (>= 0): one number for all three channels, or [r, g, b].
glm::vec3 read_conductor_channel(const Node& node, bool is_eta) {
    if (node.value().is_number()) return glm::vec3(is_eta ? node.number_at_least(0.0f, false) : node.number_at_least(0.0f, true));
    const glm::vec3 v = node.vec3();
    for (int i = 0; i < 3; ++i) {
        const Node c = node.element(static_cast<std::size_t>(i));
        if (is_eta) c.number_at_least(0.0f, false);
        else c.number_at_least(0.0f, true);
    }
    return v;
}

// {"metal": "<name>"} or {"eta": ..., "k": ...}, exactly one of the two forms.
void read_conductor(const Node& node, Material& m) {
    const auto metal = node.find("metal");
    const bool eta = node.has("eta"), k = node.has("k");
    if (metal && (eta || k)) node.fail("give either \"metal\" or \"eta\" and \"k\", not both");
    if (metal) {
        const std::string name = metal->string();
        const auto found = find_named_metal(name);
        if (!found) {
            std::string known;
            for (const NamedMetal& n : named_metals()) known += (known.empty() ? "" : ", ") + std::string(n.name);
            metal->fail("unknown metal \"" + name + "\" (known: " + known + "; or give \"eta\" and \"k\")");
        }
        m.eta = found->eta;
        m.k = found->k;
        return;
    }
    if (!eta && !k) node.fail("a conductor needs \"metal\" (a named metal) or \"eta\" and \"k\" (its complex index of refraction)");
    m.eta = read_conductor_channel(node.at("eta"), true);
    m.k = read_conductor_channel(node.at("k"), false);
}

Material read_material(const Node& node, const std::string& name, std::vector<Texture>& textures) {
    if (!node.value().is_object()) node.fail("must be an object with a \"type\"");
    const Node type_node = node.at("type");
    const std::string type = type_node.string();
    Material m;
    m.name = name;
    // A roughness in [0, 1], or a texture of it (a data map: render/materials/texture.hpp).
    auto read_roughness = [&](const Node& r) {
        if (r.value().is_object()) m.roughness_texture = add_texture(r, TextureUse::Roughness, textures);
        else m.roughness = r.number_in(0.0f, 1.0f);
    };
    // The keys every material but an emissive one takes, and its type's own.
    auto require_surface_keys = [&](std::initializer_list<std::string_view> own) {
        std::vector<std::string_view> keys = {"type", "albedo", "emission", "two_sided", "normal_map", "bump_map",
                                              "bump_scale"};
        keys.insert(keys.end(), own);
        node.require_object(keys);
    };
    if (type == "diffuse") {
        require_surface_keys({"transmittance"});
        m.type = Material::Type::Diffuse;
        if (auto t = node.find("transmittance")) m.transmittance = read_albedo(*t);
    } else if (type == "metal") {
        require_surface_keys({"roughness"});
        m.type = Material::Type::Metal;
        if (auto r = node.find("roughness")) read_roughness(*r);
    } else if (type == "conductor") {
        require_surface_keys({"roughness", "metal", "eta", "k", "distribution"});
        m.type = Material::Type::Conductor;
        m.albedo = glm::vec3(1.0f);  // untinted unless given
        read_conductor(node, m);
        if (auto r = node.find("roughness")) read_roughness(*r);
        if (auto d = node.find("distribution")) {
            const std::string name = d->string();
            if (name == "beckmann") m.microfacet = Material::Microfacet::Beckmann;
            else if (name != "ggx") d->fail("unknown distribution \"" + name + "\" (known: ggx, beckmann)");
        }
    } else if (type == "dielectric") {
        require_surface_keys({"ior"});
        m.type = Material::Type::Dielectric;
        m.albedo = glm::vec3(1.0f);  // clear glass unless tinted
        if (auto ior = node.find("ior")) m.ior = ior->number_at_least(0.0f, false);
    } else if (type == "thin_dielectric") {
        require_surface_keys({"ior"});
        m.type = Material::Type::ThinDielectric;
        m.albedo = glm::vec3(1.0f);  // clear unless tinted
        if (auto ior = node.find("ior")) m.ior = ior->number_at_least(0.0f, false);
    } else if (type == "rough_dielectric") {
        require_surface_keys({"ior", "roughness"});
        m.type = Material::Type::RoughDielectric;
        m.albedo = glm::vec3(1.0f);  // clear unless tinted
        read_roughness(node.at("roughness"));
        if (auto ior = node.find("ior")) m.ior = ior->number_at_least(0.0f, false);
    } else if (type == "coated_diffuse") {
        require_surface_keys({"ior", "roughness"});
        m.type = Material::Type::CoatedDiffuse;
        if (auto ior = node.find("ior")) m.ior = ior->number_at_least(1.0f, true);
        if (auto r = node.find("roughness")) read_roughness(*r);
    } else if (type == "interface") {
        node.require_object({"type"});
        m.type = Material::Type::Interface;
        m.albedo = glm::vec3(0.0f);
    } else if (type == "emissive") {
        node.require_object({"type", "emission", "two_sided"});
        m.type = Material::Type::Emissive;
        m.albedo = glm::vec3(0.0f);  // a light absorbs what reaches it
    } else {
        type_node.fail("unknown material type \"" + type + "\" (known: diffuse, metal, conductor, dielectric, thin_dielectric, rough_dielectric, coated_diffuse, emissive, interface)");
    }
    if (auto albedo = node.find("albedo")) {
        if (albedo->value().is_object()) {
            m.albedo_texture = add_texture(*albedo, TextureUse::Albedo, textures);
        } else {
            m.albedo = read_albedo(*albedo);
        }
    }
    if (auto emission = node.find("emission")) {
        if (emission->value().is_object()) {
            m.emission_texture = add_texture(*emission, TextureUse::Emission, textures);
            m.emission = texture_mean(textures.back());
        } else {
            m.emission = emission->vec3_at_least(0.0f);
        }
        if (m.type == Material::Type::Emissive && m.emission == glm::vec3(0.0f))
            emission->fail("an emissive material must emit: some component must be > 0");
    } else if (m.type == Material::Type::Emissive) {
        node.at("emission");  // reports it missing
    }
    if (auto two_sided = node.find("two_sided")) m.two_sided_emission = two_sided->boolean();
    if (auto normal = node.find("normal_map")) m.normal_texture = add_texture(*normal, TextureUse::NormalMap, textures);
    if (auto bump = node.find("bump_map")) m.bump_texture = add_texture(*bump, TextureUse::BumpMap, textures);
    if (auto scale = node.find("bump_scale")) {
        if (m.bump_texture < 0) scale->fail("bump_scale needs a bump_map");
        m.bump_scale = scale->number();
    }
    return m;
}

std::map<std::string, std::uint32_t> read_materials(const Node& node, std::vector<Material>& out,
                                                    std::vector<Texture>& textures) {
    if (!node.value().is_object())
        node.fail("must be an object mapping names to materials, got " + scene_json::describe_type(node.value()));
    std::map<std::string, std::uint32_t> index;
    for (const auto& item : node.value().items()) {
        const Node m = node.at(item.key());
        if (item.key().empty()) m.fail("a material name must not be empty");
        index[item.key()] = static_cast<std::uint32_t>(out.size());
        out.push_back(read_material(m, item.key(), textures));
    }
    return index;
}

// Steps apply in list order: the first step acts on the object first. `may_mirror`: negative
// scale factors are allowed (mesh objects only, below).
Transform read_transform_steps(const Node& node, bool may_mirror) {
    const std::size_t steps = node.array_size();
    glm::dmat4 m(1.0);
    for (std::size_t i = 0; i < steps; ++i) {
        const Node step = node.element(i);
        step.require_object({"translate", "rotate", "scale"});
        if (step.value().size() != 1) step.fail("each step has exactly one of \"translate\", \"rotate\", \"scale\"");
        glm::dmat4 s(1.0);
        if (auto t = step.find("translate")) {
            s = translation_matrix(glm::dvec3(t->vec3()));
        } else if (auto r = step.find("rotate")) {
            r->require_object({"axis", "degrees"});
            s = rotation_matrix(glm::dvec3(r->at("axis").nonzero_vec3()), r->at("degrees").number());
        } else {
            const Node sc = step.at("scale");
            // Positive only, but for meshes: a mirror would turn the front side of quads, disks and
            // triangles, which the scene states in world terms (edge_u x edge_v, a b c); a mesh's
            // faces keep the front its file gives them, carried like its normals (the inverse
            // transpose), as pbrt-v4 does for a transform that swaps handedness.
            const bool uniform = sc.value().is_number();
            const glm::vec3 f = uniform ? glm::vec3(sc.number()) : sc.vec3();
            for (int k = 0; k < 3; ++k) {
                if (f[k] > 0.0f || (may_mirror && f[k] < 0.0f)) continue;
                const Node factor = uniform ? sc : sc.element(static_cast<std::size_t>(k));
                if (f[k] < 0.0f) factor.fail("must be > 0: only a mesh's transform may mirror (a negative scale), got " + factor.shown());
                factor.number_at_least(0.0f, false);
            }
            s = scale_matrix(glm::dvec3(f));
        }
        m = s * m;
    }
    try {
        return Transform::from_matrix(glm::mat4(m));
    } catch (const std::invalid_argument& e) {
        node.fail(e.what());
    }
}

Transform read_transform(const Node& node) { return read_transform_steps(node, false); }

class ObjectReader {
public:
    ObjectReader(Scene& scene, std::map<std::string, std::uint32_t> materials, MediumIndex media)
        : scene_(scene), materials_(std::move(materials)), media_(std::move(media)) {}

    void read_all(const Node& objects) {
        const std::size_t n = objects.array_size();
        scene_.objects.reserve(n);
        for (std::size_t i = 0; i < n; ++i) scene_.objects.push_back(read(objects.element(i)));
    }

    // The scene's index of a mesh object's mesh (the mesh shape's home calls this): the mesh
    // given inline (inline_mesh.hpp), or the one in the OBJ or PLY file its "file" names (by its
    // extension, .ply in any case is PLY, anything else OBJ), loaded the first time.
    std::uint32_t mesh_index(const Node& object) {
        const std::optional<Node> file = object.find("file");
        for (std::string_view key : kInlineMeshKeys)
            if (object.has(key) && file) object.at(key).fail("a mesh is either a \"file\" or given inline (\"vertices\", \"indices\"), not both");
        if (!file) {
            if (!object.has("vertices")) object.fail("a mesh needs a \"file\" (OBJ or PLY) or its \"vertices\" and \"indices\" inline");
            scene_.meshes.push_back(read_inline_mesh(object));
            const auto index = static_cast<std::uint32_t>(scene_.meshes.size() - 1);
            meshes_without_materials_.insert(index);  // no materials of its own either
            return index;
        }
        return mesh_file_index(*file);
    }

    std::uint32_t mesh_file_index(const Node& file_node) {
        const std::string relative = file_node.string();
        if (relative.empty()) file_node.fail("must name an OBJ or PLY file");
        const std::filesystem::path path = scene_.source.parent_path() / relative;
        if (const std::string problem = file_kind_problem(path); !problem.empty())
            file_node.fail("mesh file \"" + relative + "\" " + problem + " (looked for " + path.string() + ")");
        std::error_code ec;
        const std::string key = std::filesystem::weakly_canonical(path, ec).string();
        if (auto it = mesh_by_file_.find(key); it != mesh_by_file_.end()) return it->second;
        // mesh.ply.gz is PLY too (the loaders inflate a .gz: gzip_file.hpp), as pbrt-v4's scenes name them.
        const bool ply = content_extension(path) == ".ply";
        ObjOutline outline;
        try {
            scene_.meshes.push_back(ply ? load_ply(path) : load_obj(path, &outline));
        } catch (const InputError& e) {
            file_node.fail(e.what());
        }
        const auto index = static_cast<std::uint32_t>(scene_.meshes.size() - 1);
        mesh_by_file_.emplace(key, index);
        if (ply) meshes_without_materials_.insert(index);
        else obj_materials_.add_mesh(index, path, std::move(outline));
        return index;
    }

    // Mesh objects with their OBJ's materials become one object per material (obj_materials.hpp).
    void split_obj_materials() { obj_materials_.split(scene_); }

private:
    Object read(const Node& node) {
        if (!node.value().is_object()) node.fail("must be an object with a \"type\"");
        const Node type_node = node.at("type");
        const std::string type = type_node.string();
        Object object;
        bool type_found = false;
        Shapes::for_each_home([&](auto home) {
            using Home = decltype(home);
            if (type_found || type != Home::kType) return;
            type_found = true;
            std::vector<std::string_view> keys{"type", "material", "transform", "name", "motion", "inside", "outside"};
            keys.insert(keys.end(), Home::kKeys.begin(), Home::kKeys.end());
            node.require_object(keys);
            object.shape = Home::read(node, *this);
        });
        if (!type_found) {
            std::string names;
            Shapes::for_each_home([&](auto home) { names += (names.empty() ? "" : ", ") + std::string(decltype(home)::kType); });
            type_node.fail("unknown shape type \"" + type + "\" (known: " + names + ")");
        }

        const auto object_index = static_cast<std::uint32_t>(scene_.objects.size());
        // A PLY or inline mesh carries no materials: its objects name one.
        const auto* instance = std::get_if<MeshInstance>(&object.shape);
        const bool no_own_materials = instance && meshes_without_materials_.count(instance->mesh) > 0;
        if (no_own_materials) {
            if (auto ms = node.find("materials"))
                ms->fail(std::string(node.has("file") ? "a PLY" : "an inline") + " mesh has no materials of its own: give the object a \"material\"");
        }
        if (auto own = no_own_materials ? std::nullopt : obj_materials_.from_obj(node, object.shape, object_index, scene_)) {
            object.material = *own;
        } else {
            const Node material = node.at("material");
            const std::string material_name = material.string();
            const auto it = materials_.find(material_name);
            if (it == materials_.end()) {
                std::string known;
                for (const auto& [name, index] : materials_) known += (known.empty() ? "" : ", ") + name;
                material.fail("unknown material \"" + material_name + "\" (defined: " + (known.empty() ? "none" : known) + ")");
            }
            object.material = it->second;
        }
        if (auto t = node.find("transform")) object.transform = read_transform_steps(*t, instance != nullptr);
        if (auto m = node.find("motion")) read_motion(*m, node, object, &read_transform);
        object.media = read_medium_interface(node, media_);
        object.name = node.has("name") ? node.at("name").string() : node.path() + " (" + type + ")";
        return object;
    }

    Scene& scene_;
    std::map<std::string, std::uint32_t> materials_;
    MediumIndex media_;
    std::map<std::string, std::uint32_t> mesh_by_file_;
    std::set<std::uint32_t> meshes_without_materials_;
    ObjMaterials obj_materials_;
};

}  // namespace

Scene load_scene(const std::filesystem::path& file) {
    const LoadBudgetScope budget;
    const ReadFilesScope read;
    const std::string text = read_text_file(file, "scene", kMaxSceneFileBytes);
    Scene scene = load_scene_document(scene_json::parse(text, file), file);
    scene.input_files = read.files();
    return scene;
}

Scene load_scene_document(const nlohmann::json& doc, const std::filesystem::path& file) {
    const Node root(doc, file);
    root.require_object({"description", "camera", "film", "background", "seed", "materials", "objects", "lights", "media"});

    Scene scene;
    scene.source = file;
    if (auto d = root.find("description")) d->string();
    // Media first: the camera and the objects name them.
    const MediumIndex media = root.has("media") ? read_media(root.at("media"), scene, &read_transform) : MediumIndex{};
    scene.camera = read_camera(root.at("camera"));
    if (auto m = root.at("camera").find("medium")) scene.camera.medium = read_medium_name(*m, media);
    scene.film = read_film(root.at("film"));
    if (auto b = root.find("background")) scene.background = read_background(*b);
    if (auto s = root.find("seed")) scene.seed = s->unsigned_integer();
    ObjectReader objects(scene, read_materials(root.at("materials"), scene.materials, scene.textures), media);
    objects.read_all(root.at("objects"));
    check_texture_uv(scene, root.at("objects"));
    if (auto l = root.find("lights")) scene.lights = read_lights(*l);
    check_scene_extent(scene, root);
    objects.split_obj_materials();
    check_motion(scene, root, root.at("objects").array_size());
    return scene;
}

}  // namespace sweeptrace
