#pragma once
// A mesh's own materials: an OBJ's `mtllib` / `usemtl` read and mapped to the renderer's
// materials (the table in scenes/README.md, "OBJ materials"), for mesh objects without a scene
// `material` (or with "materials": "from_obj"). Internal to the scene loader.
//
// The loader reads objects as usual, each such object taking its first triangle's material, so
// that every check on objects (uv, extent) sees one object per JSON entry; split() then turns
// each into one object per material, each with a mesh of that material's triangles (bit-identical
// vertices, so the parts meet watertight; a mesh and its parts are made once however many objects
// instance the file).
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "raytracer/scene/json_reader.hpp"
#include "raytracer/scene/load_mtl.hpp"
#include "raytracer/scene/obj_outline.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

// One MtlMaterial as the renderer's Material (the README's table); its maps become textures
// (appended to scene.textures, files relative to `mtl`'s folder; shared as all textures are).
// Throws InputError "<mtl>: line N: ..." for a missing or unreadable map, or a map on a mesh
// without uv (`mesh_has_uv` false).
Material material_from_mtl(const MtlMaterial& m, const std::filesystem::path& mtl, bool mesh_has_uv, Scene& scene);

class ObjMaterials {
public:
    // A mesh the loader read: its OBJ file and outline (load_obj hands it back).
    void add_mesh(std::uint32_t mesh, std::filesystem::path obj, ObjOutline outline);

    // For a mesh object (`shape`, JSON `node`, about to be scene.objects[object]) that takes its
    // materials from its OBJ, the material of its first triangle; nullopt when the object is not
    // a mesh or names its scene `material`. Fails at `node` for both "material" and
    // "materials", a "materials" other than "from_obj", or an OBJ without mtllib; OBJ and .mtl
    // errors (InputError naming the file and line) at node.file.
    std::optional<std::uint32_t> from_obj(const scene_json::Node& node, const Shape& shape, std::uint32_t object,
                                          Scene& scene);

    // Splits every object from_obj returned a material for into one object per material.
    void split(Scene& scene);

private:
    struct Source {
        std::filesystem::path obj;
        ObjOutline outline;
        std::vector<std::uint32_t> triangle_material;  // scene material per triangle, once read
    };
    const std::vector<std::uint32_t>& triangle_materials(std::uint32_t mesh, Scene& scene);

    std::map<std::uint32_t, Source> sources_;
    std::vector<std::uint32_t> objects_;  // scene objects to split
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> parts_;  // (mesh, material) -> part mesh
};

}  // namespace sweeptrace
