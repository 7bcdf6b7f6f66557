#include "raytracer/scene/pbrt/pbrt_import.hpp"

#include <charconv>
#include <optional>
#include <string_view>

#include "raytracer/input_error.hpp"
#include "raytracer/load_budget.hpp"
#include "raytracer/scene/gzip_file.hpp"
#include "raytracer/scene/json_reader.hpp"
#include "raytracer/scene/load_scene_document.hpp"
#include "raytracer/scene/pbrt/pbrt_diagnostics.hpp"
#include "raytracer/scene/pbrt/pbrt_materials.hpp"
#include "raytracer/scene/pbrt/pbrt_parser.hpp"
#include "raytracer/scene/pbrt/pbrt_world.hpp"
#include "raytracer/scene/read_files.hpp"

namespace sweeptrace {

namespace {

struct Translation {
    nlohmann::json doc;
    pbrt::DocumentOrigins origins;  // which statement wrote which part
};

Translation translate(const std::filesystem::path& file, const std::filesystem::path& output_dir, bool strict,
                      std::vector<std::string>& warnings, std::string& film_filename) {
    pbrt::Diagnostics diag(strict);
    const pbrt::FileNames files(file, output_dir);
    pbrt::MaterialTranslator materials(files, diag);
    const pbrt::PbrtScene scene = pbrt::parse_pbrt(file, materials, files, diag);
    Translation t;
    t.doc = pbrt::write_world(scene, materials, files, diag, film_filename, t.origins);
    diag.throw_if_strict();
    warnings = diag.warnings();
    return t;
}

// The JSON loader's message "<json>: <path>: <what>" said at the pbrt statement that wrote that
// part of the document: "<pbrt file>:<line>: Shape \"plymesh\": <rest of path>: <what>". Objects
// and lights by index, materials and media by name, and the camera, film and background. A
// complaint about a "file" (the mesh or VDB reader's, which names the file itself) loses the JSON path;
// one about another key keeps the key. nullopt for any other message.
std::optional<std::string> said_at_statement(std::string_view message, const std::string& json_name,
                                             const pbrt::DocumentOrigins& origins) {
    const std::string prefix = json_name + ": ";
    if (!message.starts_with(prefix)) return std::nullopt;
    std::string_view rest = message.substr(prefix.size());
    const pbrt::ObjectOrigin* origin = nullptr;
    const auto take = [&](std::string_view lead) {
        if (!rest.starts_with(lead)) return false;
        rest.remove_prefix(lead.size());
        return true;
    };
    const auto indexed = [&](const std::vector<pbrt::ObjectOrigin>& list) -> const pbrt::ObjectOrigin* {
        std::size_t index = 0;
        const auto [after, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), index);
        if (ec != std::errc() || after == rest.data() + rest.size() || *after != ']' || index >= list.size()) return nullptr;
        rest.remove_prefix(static_cast<std::size_t>(after + 1 - rest.data()));
        return &list[index];
    };
    if (take("objects[")) origin = indexed(origins.objects);
    else if (take("lights[")) origin = indexed(origins.lights);
    else if (origins.camera && take("camera")) origin = &*origins.camera;
    else if (origins.film && take("film")) origin = &*origins.film;
    else if (origins.background && take("background")) origin = &*origins.background;
    else
        for (const auto& [table, named] : {std::pair{"materials", &origins.materials}, std::pair{"media", &origins.media}})
            if (rest.starts_with(table))
                for (const auto& [name, o] : *named) {
                    const std::string key = scene_json::key_component(table, name);
                    if (rest.starts_with(key) && rest.size() > key.size() && (rest[key.size()] == '.' || rest[key.size()] == ':')) {
                        rest.remove_prefix(key.size());
                        origin = &o;
                        break;
                    }
                }
    if (!origin) return std::nullopt;
    for (const std::string_view lead : {".file: ", ": ", "."}) {
        if (rest.starts_with(lead)) {
            rest.remove_prefix(lead.size());
            break;
        }
    }
    return origin->where.text() + ": " + origin->what + ": " + std::string(rest);
}

// load_scene_document for the translation, its complaints about objects said at the pbrt file
// and line: the user of a .pbrt never saw the JSON (`json_file` stands for it in messages).
Scene load_translation(const Translation& t, const std::filesystem::path& json_file) {
    try {
        return load_scene_document(t.doc, json_file);
    } catch (const InputError& e) {
        if (std::optional<std::string> m = said_at_statement(e.what(), json_file.string(), t.origins)) throw InputError(*m);
        throw;
    }
}

}  // namespace

PbrtConversion convert_pbrt(const std::filesystem::path& file, const std::filesystem::path& output, bool strict,
                            bool validate) {
    const LoadBudgetScope budget;
    const ReadFilesScope read;
    PbrtConversion out;
    const Translation t = translate(file, output.parent_path(), strict, out.warnings, out.film_filename);
    out.json_text = t.doc.dump(2) + "\n";
    if (validate) (void)load_translation(t, output);
    out.input_files = read.files();
    return out;
}

Scene load_pbrt_scene(const std::filesystem::path& file, bool strict, std::vector<std::string>& warnings,
                      std::string* film_filename) {
    const LoadBudgetScope budget;
    const ReadFilesScope read;
    std::string film;
    const Translation t = translate(file, file.parent_path(), strict, warnings, film);
    if (film_filename) *film_filename = film;
    Scene scene = load_translation(t, file);
    scene.input_files = read.files();
    return scene;
}

bool is_pbrt_file(const std::filesystem::path& file) { return content_extension(file) == ".pbrt"; }

}  // namespace sweeptrace
