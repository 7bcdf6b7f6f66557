#pragma once
// Tangent-space normal maps and bump maps: the frame a map's texel is read in, and the shading
// normal it gives.
//
// The frame at a hit (MikkTSpace's convention, per triangle or per point rather than per
// vertex): N = the shading normal before the map (interpolated vertex normals, or the geometric
// normal), T = d(point)/du made orthogonal to N, B = N x T, turned to dpdv's side when the uv
// map is mirrored there. A texel c in [0, 1]^3 (linear data, not sRGB) encodes m = 2 c - 1, the
// new normal m.x T + m.y B + m.z N, normalised: a flat texel (0.5, 0.5, 1) keeps N; green is +v
// ("OpenGL" normal maps; DirectX maps need their green channel inverted).
// A bump map (Blinn 1978, as pbrt's BumpMap without its dn/du term, which scales with the height
// and is negligible for heights small against the curvature radius): the surface displaced by
// h(u, v) along N has tangents T' = T + dh/du N and B' = B + dh/dv N (T, B: dpdu, dpdv made
// orthogonal to N, so a height of zero slope keeps N exactly), and normal T' x B', on N's side.
// The slope is the caller's (render/materials/texture.cpp: central differences one texel apart).
// d(point)/du, d(point)/dv come from the shape's home (geometry/shapes/<shape>, uv_tangents;
// meshes from each triangle's vt), mapped to the world by the object's linear part.
//
// Guards, so a map never sends light through a surface nor creates energy. The BSDFs
// (render/materials/bsdf.hpp) take reflection only with wi on wo's side of both the shading and the
// geometric normal and transmission only across the geometric one (pbrt-v3's rule, checked on
// the geometric normal, not pbrt-v4's shading-only test): no path crosses a closed surface by a
// reflection. Here: a map value or a bump map's slope that would turn the normal to or below the
// geometric plane, a degenerate tangent (a pole, a uv triangle of zero area) or a non-finite
// result keeps N. The renderer traces radiance only (camera paths), so Veach's adjoint
// correction for shading normals (|wo.ns| |wi.ng| / (|wo.ng| |wi.ns|), needed when importance is
// transported) does not apply: every BSDF's albedo is computed in its shading frame and stays
// <= 1, so a furnace gains nothing; where wo falls below the mapped normal the BSDF returns
// black (energy lost there, not gained), the known dark-facet cost of this approach (no
// Schuessler et al. 2017 microfacet normal mapping).
#include <glm/vec3.hpp>

#include "raytracer/geometry/shapes/uv_maps.hpp"
#include "raytracer/geometry/surface_hit.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

// d(point)/du and d(point)/dv at `hit`, in world space (zero where the shape has none).
UvTangents hit_uv_tangents(const Scene& scene, const SurfaceHit& hit);

// The shading normal a normal map's texel `texel` gives over shading normal `ns` (unit, on the
// side of the unit geometric normal `ng`) with world tangents `t`; `ns` itself when a guard
// above refuses it.
glm::vec3 normal_from_map(const glm::vec3& ns, const glm::vec3& ng, const UvTangents& t, const glm::vec3& texel);

// The shading normal a height field of slope (dh_du, dh_dv) in uv gives over `ns`; the same guards.
glm::vec3 normal_from_bump(const glm::vec3& ns, const glm::vec3& ng, const UvTangents& t, float dh_du, float dh_dv);

}  // namespace sweeptrace
