#pragma once
// A test seam, kept out of the renderer's public header: defects planted on purpose, for the
// golden-image mutation tests only. They show that the image tests reject a renderer with this
// bug. Nothing in the program sets them; only tests call render_with_planted_defect.
#include "raytracer/render/renderer.hpp"

namespace sweeptrace {

// BdptDropsNee: bidirectional path tracing leaves next event estimation out of its MIS sums
// (integrators/bidir_mis.hpp), so its weights sum to more than 1 and the image is too bright.
// VcmDropsMerges: vertex connection and merging leaves the merges out of its connection
// strategies' MIS sums (integrators/bidir_mis.hpp): paths both find are counted up to twice.
enum class PlantedDefect { None, FlippedNormals, NoRayOffset, BdptDropsNee, VcmDropsMerges };

// render() with `defect` planted in the light sampler and the integrator.
RenderResult render_with_planted_defect(const Scene& scene, const Accel& accel, const RenderOptions& options,
                                        PlantedDefect defect);

}  // namespace sweeptrace
