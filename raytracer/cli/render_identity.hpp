#pragma once
// What identifies a render for the farm (image/partial_image.hpp): the scene's content hash,
// the film size, seed, depth, integrator, sampler and spp after the command line's overrides, the accelerator,
// the adaptive sampling mode, whether feature outputs are on (film.aovs after render --aovs) and the
// program version.
#include <filesystem>
#include <string>

#include "raytracer/image/partial_image.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

// FNV-1a 64 over the scene file's bytes and, in load order, the bytes of every mesh file it
// loaded (Mesh::source) and of every material library those named, then every texture and
// environment image as loaded: the same content hashes the same wherever the files live
// (another machine, another folder); a change to any of them changes the hash. Not cryptographic.
// Throws InputError when a file cannot be read.
std::string scene_content_hash(const Scene& scene, const std::filesystem::path& scene_file);

// `scene` with its overrides applied (film size, spp, max_depth, seed, integrator, sampler); `adaptive` is render
// --adaptive's value ("off", "on", "relative"), since parts of different allocations never merge.
RenderIdentity render_identity(const Scene& scene, const std::filesystem::path& scene_file, const std::string& accel,
                               const std::string& adaptive);

}  // namespace sweeptrace
