#include "raytracer/render/materials/texture.hpp"

#include <cmath>

#include <glm/common.hpp>

#include "raytracer/render/materials/shading_frame.hpp"

namespace sweeptrace {

namespace {

int wrap_index(int i, int n, Texture::Wrap wrap) {
    if (wrap == Texture::Wrap::Clamp) return i < 0 ? 0 : (i >= n ? n - 1 : i);
    if (wrap == Texture::Wrap::Mirror) {
        int m = i % (2 * n);
        if (m < 0) m += 2 * n;
        return m < n ? m : 2 * n - 1 - m;
    }
    const int m = i % n;
    return m < 0 ? m + n : m;
}

glm::vec3 lerp(const glm::vec3& a, const glm::vec3& b, float t) { return a + t * (b - a); }

glm::vec3 bilinear(const Texture& t, const glm::vec2& uv) {
    const Image& img = *t.image;
    const float x = uv.x * static_cast<float>(img.width) - 0.5f;
    const float y = (1.0f - uv.y) * static_cast<float>(img.height) - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y);
    const float ax = x - fx, ay = y - fy;
    const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
    auto at = [&](int i, int j) { return img.at(wrap_index(i, img.width, t.wrap), wrap_index(j, img.height, t.wrap)); };
    return lerp(lerp(at(x0, y0), at(x0 + 1, y0), ax), lerp(at(x0, y0 + 1), at(x0 + 1, y0 + 1), ax), ay);
}

const Texture& texture(const Scene& scene, int index) { return scene.textures[static_cast<std::size_t>(index)]; }

// A scalar parameter's value from a texel: the mean, exact for a grey texel.
float channel_mean(const glm::vec3& c) { return c.x + ((c.y - c.x) + (c.z - c.x)) / 3.0f; }

float height(const Texture& t, const glm::vec2& uv) { return channel_mean(eval_texture(t, uv)); }

// (dh/du, dh/dv) of a bump map (an image: the loader refuses checkers) by central differences
// one texel to either side: the finest slope the bilinear height has, and over two texels, so
// the difference does not jump at each texel centre as a one-sided one would.
glm::vec2 height_slope(const Texture& t, const glm::vec2& uv) {
    const float du = 1.0f / static_cast<float>(t.image->width), dv = 1.0f / static_cast<float>(t.image->height);
    return {(height(t, {uv.x + du, uv.y}) - height(t, {uv.x - du, uv.y})) / (2.0f * du),
            (height(t, {uv.x, uv.y + dv}) - height(t, {uv.x, uv.y - dv})) / (2.0f * dv)};
}

}  // namespace

glm::vec3 eval_texture(const Texture& t, const glm::vec2& surface_uv) {
    const glm::vec2 uv = t.uv_scale * surface_uv + t.uv_offset;  // exact for the identity mapping
    if (t.kind == Texture::Kind::Checker) {
        const float s = std::floor(t.scale * uv.x) + std::floor(t.scale * uv.y);
        return std::fmod(std::abs(s), 2.0f) == 0.0f ? t.a : t.b;
    }
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return glm::vec3(0.0f);
    const glm::vec3 v = bilinear(t, uv);
    if (t.multiply == glm::vec3(1.0f) && !t.invert) return v;
    const glm::vec3 scaled = t.multiply * v;
    return glm::clamp(t.invert ? glm::vec3(1.0f) - scaled : scaled, glm::vec3(t.min_value), glm::vec3(t.max_value));
}

glm::vec2 hit_uv(const Scene& scene, const SurfaceHit& hit) {
    const Object& obj = scene.objects[hit.object];
    const glm::vec3 p(obj.transform.to_object * glm::vec4(hit.point, 1.0f));
    return visit_shape(obj.shape, [&](auto home, const auto& g) -> glm::vec2 {
        using Home = decltype(home);
        if constexpr (requires { Home::uv(g, p); }) return Home::uv(g, p);
        else if constexpr (requires { Home::mesh_uv(g, scene.meshes, hit.primitive, p); })
            return Home::mesh_uv(g, scene.meshes, hit.primitive, p);
        else return glm::vec2(0.0f);
    });
}

MaterialParameters textured_material(const Scene& scene, const MaterialParameters& base, SurfaceHit& hit) {
    MaterialParameters m = base;  // the parameters alone: no name to copy
    const glm::vec2 uv = hit_uv(scene, hit);
    if (base.albedo_texture >= 0) m.albedo = eval_texture(texture(scene, base.albedo_texture), uv);
    if (base.roughness_texture >= 0) {
        m.roughness = channel_mean(eval_texture(texture(scene, base.roughness_texture), uv));
    }
    if (base.emission_texture >= 0) m.emission = eval_texture(texture(scene, base.emission_texture), uv);
    if (base.normal_texture >= 0 || base.bump_texture >= 0) {
        const UvTangents tangents = hit_uv_tangents(scene, hit);
        if (base.normal_texture >= 0)
            hit.shading_normal = normal_from_map(hit.shading_normal, hit.normal, tangents,
                                                 eval_texture(texture(scene, base.normal_texture), uv));
        if (base.bump_texture >= 0) {
            const glm::vec2 slope = base.bump_scale * height_slope(texture(scene, base.bump_texture), uv);
            hit.shading_normal = normal_from_bump(hit.shading_normal, hit.normal, tangents, slope.x, slope.y);
        }
    }
    return m;
}

glm::vec3 textured_emission(const Scene& scene, const MaterialParameters& m, const SurfaceHit& at) {
    return eval_texture(texture(scene, m.emission_texture), hit_uv(scene, at));
}

}  // namespace sweeptrace
