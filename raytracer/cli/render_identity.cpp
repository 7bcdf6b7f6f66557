#include "raytracer/cli/render_identity.hpp"

#include <cstdio>
#include <cstring>

#include "raytracer/cli/program_version.hpp"
#include "raytracer/image/image_formats.hpp"

namespace sweeptrace {
namespace {

void fnv1a(std::uint64_t& h, const std::vector<unsigned char>& bytes) {
    for (unsigned char b : bytes) h = (h ^ b) * 0x100000001b3ull;
    // The length ends each file's bytes, so two files cannot run into each other.
    for (int i = 0; i < 8; ++i) h = (h ^ ((bytes.size() >> (8 * i)) & 0xffu)) * 0x100000001b3ull;
}

// An image as loaded (so a texture or environment file that changes, changes the hash), with
// its size; the pixels' float bits in order.
void fnv1a(std::uint64_t& h, const Image& image) {
    std::vector<unsigned char> bytes(image.pixels.size() * sizeof(glm::vec3) + 2 * sizeof(int));
    std::memcpy(bytes.data(), &image.width, sizeof(int));
    std::memcpy(bytes.data() + sizeof(int), &image.height, sizeof(int));
    if (!image.pixels.empty()) std::memcpy(bytes.data() + 2 * sizeof(int), image.pixels.data(), image.pixels.size() * sizeof(glm::vec3));
    fnv1a(h, bytes);
}

}  // namespace

std::string scene_content_hash(const Scene& scene, const std::filesystem::path& scene_file) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    fnv1a(h, formats::read_bytes(scene_file));
    for (const Mesh& mesh : scene.meshes) fnv1a(h, formats::read_bytes(mesh.source));
    for (const std::filesystem::path& mtl : scene.material_libraries) fnv1a(h, formats::read_bytes(mtl));
    for (const Texture& t : scene.textures)
        if (t.image) fnv1a(h, *t.image);
    if (scene.background.environment) fnv1a(h, *scene.background.environment);
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

RenderIdentity render_identity(const Scene& scene, const std::filesystem::path& scene_file, const std::string& accel,
                               const std::string& adaptive) {
    RenderIdentity id;
    id.scene_hash = scene_content_hash(scene, scene_file);
    id.width = scene.film.width;
    id.height = scene.film.height;
    id.seed = scene.seed;
    id.max_depth = scene.film.max_depth;
    id.accel = accel;
    id.integrator = integrator_name(scene.film.integrator);
    id.sampler = sampler_name(scene.film.sampler);
    id.adaptive = adaptive;
    id.aovs = scene.film.aovs ? "on" : "off";
    id.version = program_version();
    id.spp = scene.film.spp;
    return id;
}

}  // namespace sweeptrace
