#include "raytracer/scene/load_texture.hpp"

#include <string>
#include <system_error>
#include <type_traits>

#include "raytracer/geometry/shape.hpp"
#include "raytracer/scene/load_image_file.hpp"

namespace sweeptrace {

namespace {

glm::vec3 read_colour01(const scene_json::Node& node) {
    const glm::vec3 v = node.vec3_at_least(0.0f);
    for (int i = 0; i < 3; ++i)
        if (v[i] > 1.0f) node.element(static_cast<std::size_t>(i)).number_in(0.0f, 1.0f);
    return v;
}

}  // namespace

Texture read_texture(const scene_json::Node& node, const std::vector<Texture>& loaded) {
    node.require_object({"checker", "image"});
    if (node.value().size() != 1) node.fail("give exactly one of \"checker\" or \"image\" (or a colour [r, g, b])");
    Texture t;
    if (auto c = node.find("checker")) {
        c->require_object({"a", "b", "scale"});
        t.kind = Texture::Kind::Checker;
        if (auto a = c->find("a")) t.a = read_colour01(*a);
        if (auto b = c->find("b")) t.b = read_colour01(*b);
        if (auto s = c->find("scale")) t.scale = s->number_at_least(0.0f, false);
        return t;
    }
    const scene_json::Node im = node.at("image");
    im.require_object({"file", "wrap"});
    t.kind = Texture::Kind::Image;
    const scene_json::Node file = im.at("file");
    std::error_code ec;
    t.image_file = std::filesystem::weakly_canonical(file.file().parent_path() / file.string(), ec);
    for (const Texture& other : loaded)
        if (other.image && other.image_file == t.image_file) t.image = other.image;
    if (!t.image) t.image = read_image_file(file, "texture image");
    for (const glm::vec3& p : t.image->pixels)
        for (int k = 0; k < 3; ++k)
            if (!(p[k] >= 0.0f && p[k] <= 1.0f)) im.at("file").fail("an albedo texture's values must lie in [0, 1]");
    if (auto w = im.find("wrap")) {
        const std::string wrap = w->string();
        if (wrap == "repeat") t.wrap = Texture::Wrap::Repeat;
        else if (wrap == "clamp") t.wrap = Texture::Wrap::Clamp;
        else w->fail("unknown wrap mode \"" + wrap + "\" (known: repeat, clamp)");
    }
    return t;
}

void check_texture_uv(const Scene& scene, const scene_json::Node& objects) {
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& obj = scene.objects[i];
        if (scene.materials[obj.material].albedo_texture < 0) continue;
        const bool has_uv = visit_shape(obj.shape, [&](auto home, const auto& g) {
            if constexpr (std::is_same_v<std::decay_t<decltype(g)>, MeshInstance>)
                return !scene.meshes[g.mesh].vertex_uvs.empty();
            else
                return requires { decltype(home)::uv(g, glm::vec3(0.0f)); };
        });
        if (!has_uv) {
            std::string with;
            Shapes::for_each_home([&](auto home) {
                using Home = decltype(home);
                if constexpr (requires(const typename Home::Geometry& g) { Home::uv(g, glm::vec3(0.0f)); })
                    with += (with.empty() ? "" : ", ") + std::string(Home::kType);
            });
            objects.element(i).at("material").fail("material \"" + scene.materials[obj.material].name +
                                                   "\" reads a texture, but this mesh has no uv coordinates (its OBJ "
                                                   "gives no vt on some face corner; shapes with uv: " + with +
                                                   ", and meshes whose faces all carry vt)");
        }
    }
}

}  // namespace sweeptrace
