#pragma once
// The subpaths' vertices in the path's order, for bidir_mis.hpp: the window of densities around
// one connection or merge, and the tails each vertex carries so that the window is all a weight
// needs (bdpt.cpp's strategies, vcm.cpp's merges). Light subpath vertex b is x_b; camera subpath
// vertex j is x_{k-j}. A vertex's own density is from_light for a light subpath's, from_camera
// for a camera subpath's, and its pdf_other the other one.
#include <span>

#include "raytracer/render/integrators/bidir_mis.hpp"
#include "raytracer/render/integrators/path_vertex.hpp"

namespace sweeptrace {

// The MIS quantities of light[b] (b >= 1), once the walk has set light[b - 1]'s pdf_other (its
// density from light[b] as the camera's direction would sample it): its predecessor's densities,
// the tail before it grown by one vertex from light[b - 1]'s, x_0's densities from light[0]
// (pdf_own, pdf_nee) and whether x_0 can be hit (`light_hittable`).
LightVertexMis light_vertex_mis(std::span<const PathVertex> light, int b, bool light_hittable, float eta,
                                MisDefect defect);
// x_0's own: emission's and NEE's densities, depth 0.
LightVertexMis light_origin_mis(const PathVertex& x0, bool light_hittable);

// cam[j]'s tail after cam[j - 2] (0 for j < 3), from cam[j - 1]'s; cam[j - 2]'s pdf_other set.
MisTail camera_vertex_above(std::span<const PathVertex> cam, int j, float eta, MisDefect defect);

// The light subpath's end in the window: y = x_b with `mis` (m.lo = b - 1, or 0 for b = 0):
// x_b's own density, x_{b-1} with its density from x_b (`pdf_to_prev` per unit solid angle at
// x_b: x_b's BSDF for a connection, the camera vertex's for a merge, as SmallVCM's), the tail and
// x_0's densities. x_b's from_camera and delta flag are the caller's.
void put_light_end(MisPath& m, const LightVertexMis& y, float pdf_to_prev);

// The camera subpath's end: cam[j] as x_s with from_light `fl_s`, cam[j - 1] with from_light
// `fl_next` (ignored when cam[j - 1] is the lens), cam[j - 2] and cam[j]'s tail after it
// (m.hi = s + min(j, 2)). cam[j]'s delta flag is cleared (the technique's end) unless `keep_delta`.
void put_camera_end(MisPath& m, std::span<const PathVertex> cam, int j, int s, float fl_s, float fl_next,
                    bool keep_delta = false);

}  // namespace sweeptrace
