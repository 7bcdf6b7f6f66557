#include "raytracer/scene/load_texture.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <system_error>
#include <type_traits>

#include <glm/common.hpp>

#include "raytracer/geometry/shape.hpp"
#include "raytracer/image/srgb.hpp"
#include "raytracer/scene/load_image_file.hpp"

namespace sweeptrace {

namespace {

bool is_data(TextureUse use) {
    return use == TextureUse::Roughness || use == TextureUse::NormalMap || use == TextureUse::BumpMap;
}

glm::vec3 read_colour01(const scene_json::Node& node) {
    const glm::vec3 v = node.vec3_at_least(0.0f);
    for (int i = 0; i < 3; ++i)
        if (v[i] > 1.0f) node.element(static_cast<std::size_t>(i)).number_in(0.0f, 1.0f);
    return v;
}

glm::vec3 read_checker_value(const scene_json::Node& node, TextureUse use) {
    if (use == TextureUse::Roughness) return glm::vec3(node.number_in(0.0f, 1.0f));
    if (use == TextureUse::Emission) return node.vec3_at_least(0.0f);
    return read_colour01(node);
}

// An sRGB-coded image (.png, .jpg, .tga: is_8bit_srgb) the other way round: the reader decodes
// sRGB, so a data map re-encodes (and rounds to the nearest 16-bit code: an 8-bit code k comes
// back as exactly k / 255, since k / 255 = 257 k / 65535), and a colour map decodes a data map
// loaded before it.
std::shared_ptr<const Image> converted(const Image& from, bool to_data) {
    Image out = from;
    for (glm::vec3& p : out.pixels)
        for (int k = 0; k < 3; ++k)
            p[k] = to_data ? static_cast<float>(std::lround(static_cast<double>(srgb_encode(p[k])) * 65535.0)) / 65535.0f
                           : srgb_decode(p[k]);
    return std::make_shared<const Image>(std::move(out));
}

void check_values(const Image& image, TextureUse use, const ImageFail& fail) {
    const char* what = use == TextureUse::Albedo      ? "an albedo"
                       : use == TextureUse::Roughness ? "a roughness"
                       : use == TextureUse::NormalMap ? "a normal map"
                       : use == TextureUse::BumpMap   ? "a bump map"
                                                      : "an emission";
    for (const glm::vec3& p : image.pixels)
        for (int k = 0; k < 3; ++k) {
            if (use == TextureUse::Emission) {
                if (!(p[k] >= 0.0f) || !std::isfinite(p[k])) fail("an emission texture's values must be finite and >= 0");
            } else if (use == TextureUse::BumpMap) {
                // A height in world units, of either sign (a .exr displacement map's).
                if (!std::isfinite(p[k])) fail("a bump map's values must be finite");
            } else if (!(p[k] >= 0.0f && p[k] <= 1.0f)) {
                fail(std::string(what) + " texture's values must lie in [0, 1]");
            }
        }
}

// [a, b], each finite; `nonzero`: neither 0 (a scale that would flatten the pattern to a point).
glm::vec2 read_vec2(const scene_json::Node& node, bool nonzero) {
    if (node.array_size() != 2) node.fail("must be an array of 2 numbers, got " + node.shown());
    glm::vec2 v;
    for (int i = 0; i < 2; ++i) {
        const scene_json::Node e = node.element(static_cast<std::size_t>(i));
        v[i] = e.number();
        if (nonzero && v[i] == 0.0f) e.fail("must not be 0");
    }
    return v;
}

// The uv mapping both kinds take (scene.hpp: Texture).
void read_uv_mapping(const scene_json::Node& node, Texture& t) {
    if (auto s = node.find("uv_scale")) t.uv_scale = read_vec2(*s, true);
    if (auto o = node.find("uv_offset")) t.uv_offset = read_vec2(*o, false);
}

void read_image_texture(const scene_json::Node& im, TextureUse use, const std::vector<Texture>& loaded, Texture& t) {
    im.require_object({"file", "wrap", "uv_scale", "uv_offset", "multiply", "invert", "encoding"});
    const scene_json::Node file = im.at("file");
    const std::string relative = file.string();
    std::optional<bool> linear;
    if (auto e = im.find("encoding")) {
        const std::string enc = e->string();
        if (enc != "sRGB" && enc != "linear") e->fail("must be \"sRGB\" or \"linear\", got " + e->shown());
        linear = enc == "linear";
    }
    t = image_texture(relative, file.file().parent_path() / relative, use, loaded,
                      [&](const std::string& message) { file.fail(message); }, linear);
    if (auto w = im.find("wrap")) {
        const std::string wrap = w->string();
        if (wrap == "repeat") t.wrap = Texture::Wrap::Repeat;
        else if (wrap == "clamp") t.wrap = Texture::Wrap::Clamp;
        else if (wrap == "mirror") t.wrap = Texture::Wrap::Mirror;
        else w->fail("unknown wrap mode \"" + wrap + "\" (known: repeat, clamp, mirror)");
    }
    read_uv_mapping(im, t);
    if (auto m = im.find("multiply")) t.multiply = m->value().is_number() ? glm::vec3(m->number()) : m->vec3();
    if (auto inv = im.find("invert")) {
        t.invert = inv->boolean();
        // The emission light's texel sampling and its mean assume the texels are the radiance.
        if (t.invert && use == TextureUse::Emission) inv->fail("an emission texture cannot be inverted");
    }
}

}  // namespace

Texture image_texture(const std::string& relative, const std::filesystem::path& path, TextureUse use,
                      const std::vector<Texture>& loaded, const ImageFail& fail, std::optional<bool> linear) {
    Texture t;
    t.kind = Texture::Kind::Image;
    t.linear_data = linear.value_or(is_data(use));
    // The parameter's range, which a multiplied or inverted value is kept in: a bump map's height
    // is any number (pbrt's displacement may be negative), an emission any radiance.
    constexpr float inf = std::numeric_limits<float>::infinity();
    t.min_value = use == TextureUse::BumpMap ? -inf : 0.0f;
    t.max_value = use == TextureUse::Emission || use == TextureUse::BumpMap ? inf : 1.0f;
    std::error_code ec;
    t.image_file = std::filesystem::weakly_canonical(path, ec);
    const bool srgb8 = is_8bit_srgb(t.image_file);  // .png, .jpg or .tga
    // The same reading if one is loaded; else the other reading of an 8-bit sRGB file, converted.
    const Texture* other_reading = nullptr;
    for (const Texture& other : loaded) {
        if (!other.image || other.image_file != t.image_file) continue;
        if (!srgb8 || other.linear_data == t.linear_data) t.image = other.image;
        else if (!other_reading) other_reading = &other;
    }
    if (!t.image && other_reading) t.image = converted(*other_reading->image, t.linear_data);
    if (!t.image) {
        t.image = read_image_path(relative, path, "texture image", fail);
        if (srgb8 && t.linear_data) t.image = converted(*t.image, true);
    }
    check_values(*t.image, use, fail);
    return t;
}

Texture read_texture(const scene_json::Node& node, TextureUse use, const std::vector<Texture>& loaded) {
    node.require_object({"checker", "image"});
    if (node.value().size() != 1) node.fail("give exactly one of \"checker\" or \"image\" (or a plain value)");
    Texture t;
    if (auto c = node.find("checker")) {
        // A bump map's normal comes from the height's slope, which a checker has only at its
        // edges, where it is a step: no slope to take.
        if (use == TextureUse::BumpMap) c->fail("a bump map must be an image (a checker's height has no slope)");
        c->require_object({"a", "b", "scale", "uv_scale", "uv_offset"});
        t.kind = Texture::Kind::Checker;
        if (auto a = c->find("a")) t.a = read_checker_value(*a, use);
        if (auto b = c->find("b")) t.b = read_checker_value(*b, use);
        if (auto s = c->find("scale")) t.scale = s->number_at_least(0.0f, false);
        read_uv_mapping(*c, t);
        return t;
    }
    read_image_texture(node.at("image"), use, loaded, t);
    return t;
}

int add_texture(const scene_json::Node& node, TextureUse use, std::vector<Texture>& textures) {
    textures.push_back(read_texture(node, use, textures));
    return static_cast<int>(textures.size() - 1);
}

glm::vec3 texture_mean(const Texture& t) {
    if (t.kind == Texture::Kind::Checker) return 0.5f * (t.a + t.b);
    glm::dvec3 sum(0.0);
    for (const glm::vec3& p : t.image->pixels) {
        glm::vec3 v = t.multiply * p;
        if (t.invert) v = glm::vec3(1.0f) - v;
        sum += glm::dvec3(glm::clamp(v, glm::vec3(t.min_value), glm::vec3(t.max_value)));
    }
    return glm::vec3(sum / static_cast<double>(t.image->pixels.size()));
}

void check_texture_uv(const Scene& scene, const scene_json::Node& objects) {
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& obj = scene.objects[i];
        if (!reads_texture(scene.materials[obj.material])) continue;
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
