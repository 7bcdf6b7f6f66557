#include "raytracer/scene/pbrt_import.hpp"

#include "raytracer/scene/gzip_file.hpp"
#include "raytracer/scene/load_scene_document.hpp"
#include "raytracer/scene/pbrt_diagnostics.hpp"
#include "raytracer/scene/pbrt_materials.hpp"
#include "raytracer/scene/pbrt_parser.hpp"
#include "raytracer/scene/pbrt_world.hpp"

namespace sweeptrace {

namespace {

nlohmann::json translate(const std::filesystem::path& file, const std::filesystem::path& output_dir, bool strict,
                         std::vector<std::string>& warnings, std::string& film_filename) {
    pbrt::Diagnostics diag(strict);
    const pbrt::FileNames files(file, output_dir);
    pbrt::MaterialTranslator materials(files, diag);
    const pbrt::PbrtScene scene = pbrt::parse_pbrt(file, materials, files, diag);
    nlohmann::json doc = pbrt::write_world(scene, materials, files, diag, film_filename);
    diag.throw_if_strict();
    warnings = diag.warnings();
    return doc;
}

}  // namespace

PbrtConversion convert_pbrt(const std::filesystem::path& file, const std::filesystem::path& output, bool strict,
                            bool validate) {
    PbrtConversion out;
    const nlohmann::json doc = translate(file, output.parent_path(), strict, out.warnings, out.film_filename);
    out.json_text = doc.dump(2) + "\n";
    if (validate) (void)load_scene_document(doc, output);
    return out;
}

Scene load_pbrt_scene(const std::filesystem::path& file, bool strict, std::vector<std::string>& warnings,
                      std::string* film_filename) {
    std::string film;
    const nlohmann::json doc = translate(file, file.parent_path(), strict, warnings, film);
    if (film_filename) *film_filename = film;
    return load_scene_document(doc, file);
}

bool is_pbrt_file(const std::filesystem::path& file) { return content_extension(file) == ".pbrt"; }

}  // namespace sweeptrace
