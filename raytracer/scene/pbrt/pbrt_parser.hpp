#pragma once
// The pbrt-v4 statement grammar and graphics state: reads the main file and its Includes into a
// PbrtScene (pbrt_scene.hpp). The CTM, ReverseOrientation, the current material and area light
// are saved by AttributeBegin and restored by AttributeEnd (TransformBegin/End, deprecated, save
// only the CTM); CoordinateSystem names the CTM, CoordSysTransform restores a name ("camera" is
// the camera's world-from-camera, as pbrt-v4 defines it). ObjectBegin/End record shapes that
// ObjectInstance places again under its own CTM. Statements we do not support are warned about
// once per kind and skipped with their parameters.
//
// Bounds: Include/Import nesting of at most kMaxIncludeDepth, at most kMaxFiles files and
// kMaxTotalBytes of text in all, at most kMaxShapes shapes after instancing: a malicious file
// cannot make the importer loop or take unbounded memory.
#include <cstddef>
#include <filesystem>

#include "raytracer/scene/pbrt/pbrt_diagnostics.hpp"
#include "raytracer/scene/pbrt/pbrt_materials.hpp"
#include "raytracer/scene/pbrt/pbrt_scene.hpp"

namespace sweeptrace::pbrt {

inline constexpr int kMaxIncludeDepth = 16;
inline constexpr std::size_t kMaxFiles = 4096;
inline constexpr std::size_t kMaxTotalBytes = std::size_t{64} << 20;
inline constexpr std::size_t kMaxShapes = std::size_t{1} << 20;

PbrtScene parse_pbrt(const std::filesystem::path& main_file, MaterialTranslator& materials, const FileNames& files,
                     Diagnostics& diag);

}  // namespace sweeptrace::pbrt
