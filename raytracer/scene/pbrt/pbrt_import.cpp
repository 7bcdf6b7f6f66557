#include "raytracer/scene/pbrt/pbrt_import.hpp"

#include <charconv>
#include <optional>
#include <string_view>

#include "raytracer/input_error.hpp"
#include "raytracer/scene/gzip_file.hpp"
#include "raytracer/scene/load_scene_document.hpp"
#include "raytracer/scene/pbrt/pbrt_diagnostics.hpp"
#include "raytracer/scene/pbrt/pbrt_materials.hpp"
#include "raytracer/scene/pbrt/pbrt_parser.hpp"
#include "raytracer/scene/pbrt/pbrt_world.hpp"

namespace sweeptrace {

namespace {

struct Translation {
    nlohmann::json doc;
    std::vector<pbrt::ObjectOrigin> origins;  // objects[i] was written for origins[i]
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

// The JSON loader's message "<json>: objects[N]<path>: <what>" said at the pbrt statement that
// wrote objects[N]: "<pbrt file>:<line>: Shape \"plymesh\": <what>". A complaint about the
// object's "file" (the mesh loader's, which names the mesh file itself) loses the JSON path; one
// about another key keeps the key. nullopt for any other message.
std::optional<std::string> said_at_statement(std::string_view message, const std::string& json_name,
                                             const std::vector<pbrt::ObjectOrigin>& origins) {
    const std::string prefix = json_name + ": objects[";
    if (!message.starts_with(prefix)) return std::nullopt;
    const char* digits = message.data() + prefix.size();
    const char* end = message.data() + message.size();
    std::size_t index = 0;
    const auto [after, ec] = std::from_chars(digits, end, index);
    if (ec != std::errc() || after == end || *after != ']' || index >= origins.size()) return std::nullopt;
    std::string_view rest = message.substr(static_cast<std::size_t>(after + 1 - message.data()));
    for (const std::string_view lead : {".file: ", ": ", "."}) {
        if (rest.starts_with(lead)) {
            rest.remove_prefix(lead.size());
            break;
        }
    }
    return origins[index].where.text() + ": " + origins[index].what + ": " + std::string(rest);
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
    PbrtConversion out;
    const Translation t = translate(file, output.parent_path(), strict, out.warnings, out.film_filename);
    out.json_text = t.doc.dump(2) + "\n";
    if (validate) (void)load_translation(t, output);
    return out;
}

Scene load_pbrt_scene(const std::filesystem::path& file, bool strict, std::vector<std::string>& warnings,
                      std::string* film_filename) {
    std::string film;
    const Translation t = translate(file, file.parent_path(), strict, warnings, film);
    if (film_filename) *film_filename = film;
    return load_translation(t, file);
}

bool is_pbrt_file(const std::filesystem::path& file) { return content_extension(file) == ".pbrt"; }

}  // namespace sweeptrace
