#pragma once
// Wavefront .mtl files (an OBJ's `mtllib`): the statements the renderer maps to its materials,
// each remembered with its line for messages. Internal to the scene loader.
//
// Read: newmtl, Kd, Ks, Ke (three numbers, or one for grey), Ns, Ni, d, Tr (= 1 - d), illum, and
// the maps map_Kd, map_Ks, map_Bump / bump and norm (a map statement's file is its last word;
// of the options before it a bump map's -bm multiplier is applied, the others, such as -s 1 1 1,
// are read past and not applied). Other statements (Ka, Tf, map_Ka, map_d, PBR extensions, ...)
// are ignored. scenes/README.md has the table that
// maps a read material to the renderer's (materials_from_mtl).
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace sweeptrace {

struct MtlMap {
    std::string file;       // as written, relative to the .mtl's folder; empty: none
    std::size_t line = 0;
    float bm = 1.0f;        // -bm: map_Bump's and bump's height multiplier
};

struct MtlMaterial {
    std::string name;
    std::size_t line = 0;  // its newmtl
    glm::vec3 kd{0.8f}, ks{0.0f}, ke{0.0f};
    float ns = 0.0f, ni = 0.0f, d = 1.0f;
    int illum = -1;  // -1: not given
    // map_bump: map_Bump / map_bump / bump (a height map by the standard, though Blender's
    // exporter writes normal maps there: obj_materials.cpp tells them apart); map_norm: norm.
    MtlMap map_kd, map_ks, map_bump, map_norm;
};

// Throws InputError "<file>: line N: ..." for a statement whose numbers are missing, not decimal,
// or out of range (Kd and Ks in [0, 1], Ke and Ns >= 0, Ni >= 0, d and Tr in [0, 1], illum 0..10,
// a -bm multiplier finite), a property before any newmtl, an empty or repeated material name, a map without a file, or a
// file that cannot be read (as for an OBJ).
std::vector<MtlMaterial> load_mtl(const std::filesystem::path& file);

}  // namespace sweeptrace
