#include "raytracer/scene/obj_materials.hpp"

#include <algorithm>
#include <cmath>
#include <system_error>
#include <unordered_map>

#include "raytracer/input_error.hpp"
#include "raytracer/scene/load_texture.hpp"

namespace sweeptrace {

namespace {

float max3(const glm::vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }

int map_texture(const MtlMap& map, const char* key, TextureUse use, const std::filesystem::path& mtl, bool has_uv,
                Scene& scene) {
    const std::string where = mtl.string() + ": line " + std::to_string(map.line) + ": " + key + ": ";
    if (!has_uv)
        throw InputError(where + "a texture needs texture coordinates, but the OBJ gives no vt on some face corner");
    scene.textures.push_back(image_texture(map.file, mtl.parent_path() / map.file, use, scene.textures,
                                           [&](const std::string& message) { throw InputError(where + message); }));
    return static_cast<int>(scene.textures.size() - 1);
}

// Every texel's channels within 4/255 of each other: grey, allowing for the colour noise of an
// 8-bit or JPEG-compressed grey image saved as RGB. (A normal map's blue channel is above 0.5
// wherever its normal faces out, and its red and green near 0.5 where flat.)
bool is_grey(const Image& image) {
    constexpr float kTolerance = 4.0f / 255.0f;
    for (const glm::vec3& p : image.pixels)
        if (std::abs(p.x - p.y) > kTolerance || std::abs(p.y - p.z) > kTolerance || std::abs(p.x - p.z) > kTolerance)
            return false;
    return true;
}

// The faces' usemtl names, one per triangle (fans: corners - 2 triangles a face, in file order,
// as load_obj stores them); "" before the first usemtl.
std::vector<const ObjOutline::Statement*> triangle_usemtl(const ObjOutline& outline) {
    std::vector<const ObjOutline::Statement*> out;
    std::size_t next = 0;
    const ObjOutline::Statement* current = nullptr;
    for (std::size_t f = 0; f < outline.face_lines.size(); ++f) {
        while (next < outline.usemtls.size() && outline.usemtls[next].line < outline.face_lines[f])
            current = &outline.usemtls[next++];
        out.insert(out.end(), outline.face_corners[f] - 2, current);
    }
    return out;
}

// Phong exponent to GGX: alpha = sqrt(2 / (Ns + 2)) (Walter et al. 2007's match), and the
// renderer's roughness is sqrt(alpha).
float phong_to_roughness(float ns) { return static_cast<float>(std::pow(2.0 / (static_cast<double>(ns) + 2.0), 0.25)); }

}  // namespace

Material material_from_mtl(const MtlMaterial& m, const std::filesystem::path& mtl, bool has_uv, Scene& scene) {
    Material out;
    out.name = mtl.filename().string() + "/" + m.name;
    const bool glass = m.d < 1.0f || m.illum == 4 || m.illum == 6 || m.illum == 7 || m.illum == 9;
    const bool metal = !glass && (m.illum == 3 || m.illum == 5 || (max3(m.kd) == 0.0f && max3(m.ks) > 0.0f));
    if (glass) {
        out.type = Material::Type::Dielectric;
        out.albedo = glm::vec3(1.0f);
        out.ior = m.ni > 0.0f ? m.ni : 1.5f;
    } else if (metal) {
        out.type = Material::Type::Metal;
        out.albedo = m.ks;
        out.roughness = phong_to_roughness(m.ns);
        if (!m.map_ks.file.empty()) out.albedo_texture = map_texture(m.map_ks, "map_Ks", TextureUse::Albedo, mtl, has_uv, scene);
    } else {
        // A diffuse colour with a specular one is a coated (plastic-like) surface: a dielectric
        // coat whose reflection is Fresnel's (so Ks's strength and colour are not used, only
        // that there is one) over the Kd base.
        const bool coated = max3(m.ks) > 0.0f;
        out.type = coated ? Material::Type::CoatedDiffuse : Material::Type::Diffuse;
        out.albedo = m.kd;
        if (coated) {
            out.ior = m.ni > 1.0f ? m.ni : 1.5f;  // Ni 1 (or unset) on an opaque material: a typical coat
            out.roughness = phong_to_roughness(m.ns);
        }
        if (!m.map_kd.file.empty()) out.albedo_texture = map_texture(m.map_kd, "map_Kd", TextureUse::Albedo, mtl, has_uv, scene);
    }
    out.emission = m.ke;
    if (!m.map_norm.file.empty())
        out.normal_texture = map_texture(m.map_norm, "normal map", TextureUse::NormalMap, mtl, has_uv, scene);
    if (!m.map_bump.file.empty()) {
        const int bump = map_texture(m.map_bump, "bump map", TextureUse::BumpMap, mtl, has_uv, scene);
        // The standard's map_Bump is a height field; Blender's exporter writes its normal maps
        // there. A height map is grey, a tangent-space normal map is not (its flat texel is
        // (0.5, 0.5, 1)): the file says which it is.
        if (is_grey(*scene.textures[static_cast<std::size_t>(bump)].image)) {
            out.bump_texture = bump;
            out.bump_scale = m.map_bump.bm;
        } else if (out.normal_texture < 0) {
            out.normal_texture = bump;
        } else {
            throw InputError(mtl.string() + ": line " + std::to_string(m.map_bump.line) +
                             ": bump map: a coloured image (a normal map) where norm already gives one");
        }
    }
    return out;
}

void ObjMaterials::add_mesh(std::uint32_t mesh, std::filesystem::path obj, ObjOutline outline) {
    sources_[mesh] = Source{std::move(obj), std::move(outline), {}};
}

const std::vector<std::uint32_t>& ObjMaterials::triangle_materials(std::uint32_t mesh, Scene& scene) {
    Source& src = sources_.at(mesh);
    if (!src.triangle_material.empty()) return src.triangle_material;
    const std::string obj = src.obj.string();
    if (src.outline.mtllibs.empty())
        throw InputError(obj + ": names no material library (no mtllib line): give the object a \"material\"");
    struct Library {
        std::filesystem::path file;
        std::vector<MtlMaterial> materials;
    };
    std::vector<Library> libraries;
    for (const ObjOutline::Statement& lib : src.outline.mtllibs) {
        std::size_t start = 0;
        while (start < lib.value.size()) {
            const std::size_t end = std::min(lib.value.find(' ', start), lib.value.size());
            const std::string name = lib.value.substr(start, end - start);
            const std::filesystem::path file = src.obj.parent_path() / name;
            if (const std::string problem = file_kind_problem(file); !problem.empty())
                throw InputError(obj + ": line " + std::to_string(lib.line) + ": mtllib \"" + excerpt(name, 80) + "\" " + problem +
                                 " (looked for " + file.string() + ")");
            libraries.push_back({file, load_mtl(file)});
            scene.material_libraries.push_back(file);
            start = end + 1;
        }
    }
    const bool has_uv = !scene.meshes[mesh].vertex_uvs.empty();
    std::map<std::string, std::uint32_t> index;  // usemtl name ("" = none) -> scene material
    for (const ObjOutline::Statement* use : triangle_usemtl(src.outline)) {
        const std::string name = use ? use->value : std::string();
        auto it = index.find(name);
        if (it == index.end()) {
            Material m;
            m.name = src.obj.filename().string() + " (faces before any usemtl)";
            bool found = use == nullptr;
            for (const Library& lib : libraries)
                for (const MtlMaterial& mm : lib.materials)
                    if (!found && mm.name == name) {
                        m = material_from_mtl(mm, lib.file, has_uv, scene);
                        found = true;
                    }
            if (!found)
                throw InputError(obj + ": line " + std::to_string(use->line) + ": usemtl \"" + excerpt(name, 80) +
                                 "\": no such material in its mtllib files");
            scene.materials.push_back(std::move(m));
            it = index.emplace(name, static_cast<std::uint32_t>(scene.materials.size() - 1)).first;
        }
        src.triangle_material.push_back(it->second);
    }
    return src.triangle_material;
}

std::optional<std::uint32_t> ObjMaterials::from_obj(const scene_json::Node& node, const Shape& shape,
                                                    std::uint32_t object, Scene& scene) {
    const auto* instance = std::get_if<MeshInstance>(&shape);
    if (!instance) return std::nullopt;
    if (auto ms = node.find("materials")) {
        if (node.has("material")) node.fail("give either \"material\" (one for the whole mesh) or \"materials\": \"from_obj\"");
        if (ms->string() != "from_obj") ms->fail("the only value is \"from_obj\" (the OBJ's mtllib / usemtl)");
    } else if (node.has("material")) {
        return std::nullopt;
    }
    try {
        const std::uint32_t first = triangle_materials(instance->mesh, scene).front();
        objects_.push_back(object);
        return first;
    } catch (const InputError& e) {
        node.at("file").fail(e.what());
    }
}

void ObjMaterials::split(Scene& scene) {
    for (const std::uint32_t index : objects_) {
        const Object whole = scene.objects[index];
        const std::uint32_t mesh_index = std::get<MeshInstance>(whole.shape).mesh;
        const std::vector<std::uint32_t>& materials = sources_.at(mesh_index).triangle_material;
        std::vector<std::uint32_t> order;  // materials by first appearance
        for (std::uint32_t m : materials)
            if (std::find(order.begin(), order.end(), m) == order.end()) order.push_back(m);
        if (order.size() == 1) continue;
        for (std::size_t k = 0; k < order.size(); ++k) {
            auto [it, inserted] = parts_.try_emplace({mesh_index, order[k]}, 0u);
            if (inserted) {
                const Mesh& src = scene.meshes[mesh_index];
                Mesh part;
                part.source = src.source;  // the file it came from (the CLI hashes and guards it)
                std::unordered_map<std::uint32_t, std::uint32_t> remap;
                auto vertex = [&](std::uint32_t v) {
                    const auto [r, fresh] = remap.try_emplace(v, static_cast<std::uint32_t>(part.triangles.vertices.size()));
                    if (fresh) {
                        part.triangles.vertices.push_back(src.triangles.vertices[v]);
                        if (!src.vertex_normals.empty()) part.vertex_normals.push_back(src.vertex_normals[v]);
                        if (!src.vertex_uvs.empty()) part.vertex_uvs.push_back(src.vertex_uvs[v]);
                    }
                    return r->second;
                };
                for (std::size_t t = 0; t < materials.size(); ++t)
                    if (materials[t] == order[k]) {
                        const glm::uvec3 f = src.triangles.indices[t];
                        part.triangles.indices.emplace_back(vertex(f.x), vertex(f.y), vertex(f.z));
                    }
                scene.meshes.push_back(std::move(part));
                it->second = static_cast<std::uint32_t>(scene.meshes.size() - 1);
            }
            Object o = whole;
            o.shape = MeshInstance{it->second};
            o.material = order[k];
            o.name = whole.name + " [" + scene.materials[order[k]].name + "]";
            if (k == 0) scene.objects[index] = std::move(o);
            else scene.objects.push_back(std::move(o));
        }
    }
}

}  // namespace sweeptrace
