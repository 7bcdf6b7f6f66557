#pragma once
// Textures at a hit (scene.hpp: Texture). The uv comes from the hit object's shape home
// (geometry/shapes/<shape>, `uv(geometry, object_point)`), computed only here, so only for hits
// whose material reads a texture; the hit's world point is taken back to object space by the
// object's inverse transform. One uv per hit, however many parameters read textures.
//
// - checker: with s = floor(scale u) + floor(scale v), colour a where s is even, b where odd;
// - image: bilinear between the four texel centres around (u W - 1/2, (1 - v) H - 1/2) (v = 0 is
//   the image's bottom row, v = 1 its top, as in OBJ and OpenGL), as c0 + a (c1 - c0) along
//   each axis, so equal neighbours give their value exactly; wrap "repeat" takes texel indices
//   modulo the size, "clamp" clamps them to the edge, "mirror" reflects them at each edge (the
//   image, then its mirror image, period 2 W).
// Both read the pattern at the texture's uv mapping (uv_scale, uv_offset); an image's value is
// then scaled and inverted as the texture says (scene.hpp: Texture).
// A scalar parameter (roughness, a bump map's height) reads the mean of the three channels.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "raytracer/geometry/surface_hit.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

glm::vec3 eval_texture(const Texture& t, const glm::vec2& uv);

// The uv of `hit` on its object by the shape's home; (0, 0) for shapes without uv (the loader
// refuses textures on those).
glm::vec2 hit_uv(const Scene& scene, const SurfaceHit& hit);

// `base` with its textured parameters evaluated at `hit` (the caller's copy; only called for
// materials that read a texture). A normal map, then a bump map, also replace hit.shading_normal
// (render/materials/shading_frame.hpp).
MaterialParameters textured_material(const Scene& scene, const MaterialParameters& base, SurfaceHit& hit);

// What a material with an emission texture emits at a point a light sample drew (`at`: its world
// point, object and primitive), toward the side `emitted_radiance` already accepted.
glm::vec3 textured_emission(const Scene& scene, const MaterialParameters& m, const SurfaceHit& at);

}  // namespace sweeptrace
