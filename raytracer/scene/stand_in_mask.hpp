#pragma once
// Stand-in textures (a missing image replaced by a flat placeholder, as in ../shared/bitterli,
// whose README names them) and the scene that shows where they are seen: for
// `sweeptrace reference-check`, which must leave those pixels out of a comparison with a
// reference rendered with the real images. General, not per scene: any texture may be named a
// stand-in, and any image texture of at most 8 x 8 texels that all hold one colour is taken for
// one (a real texture that small and flat would be a plain colour anyway).
#include <filesystem>
#include <vector>

#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

// Indices into scene.textures: image textures whose file is one of `named` (compared as
// canonical paths) or, with `detect_flat`, whose image is flat and at most 8 x 8.
std::vector<int> stand_in_textures(const Scene& scene, const std::vector<std::filesystem::path>& named, bool detect_flat);

// A copy of `scene` in which only the surfaces whose material reads a stand-in texture emit
// (radiance 1, both sides, black otherwise) and nothing else does: lights, background and every
// other emission removed, diffuse (and coated diffuse) albedos set to 0 so that the stand-ins
// light nothing, and the specular materials (mirror, glass, metal) kept, so a stand-in seen in a
// mirror or through glass shows too. Its render at the comparison's size is, per pixel, the share
// of the pixel's paths that end on a stand-in (weighted by the specular bounces' throughput).
// `found` says whether any material reads one.
Scene stand_in_mask_scene(const Scene& scene, const std::vector<int>& stand_ins, bool& found);

}  // namespace sweeptrace
