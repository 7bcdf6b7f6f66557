// `sweeptrace convert SCENE.pbrt [-o SCENE.json] [--strict]`: a pbrt-v4 scene translated to our
// scene JSON (scene/pbrt/pbrt_import.hpp), so what was understood can be read and edited. The JSON is
// loaded as `render` would load it before it is written (atomically: all or nothing), and its
// relative file names start from the output's folder. Warnings (one per kind of thing
// approximated or ignored) go to stderr; --strict makes the first one an error (exit 2).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "raytracer/cli/commands.hpp"
#include "raytracer/cli/output_guard.hpp"
#include "raytracer/cli/report_text.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/scene/gzip_file.hpp"
#include "raytracer/scene/pbrt/pbrt_import.hpp"

namespace sweeptrace {

namespace {

struct ConvertArgs {
    std::string scene;
    std::string output;
    bool strict = false;
    bool quiet = false;
};

int run_convert(const ConvertArgs& a) {
    const std::filesystem::path in(a.scene);
    if (!is_pbrt_file(in)) throw InputError("convert reads pbrt-v4 scenes (.pbrt), got '" + a.scene + "'");
    // x.pbrt.gz -> x.json, as x.pbrt
    const std::filesystem::path plain = is_gzip_name(in) ? in.stem() : in.filename();
    const std::filesystem::path out = a.output.empty() ? std::filesystem::path(plain.stem().string() + ".json") : std::filesystem::path(a.output);
    if (out.extension() != ".json") throw InputError("output '" + out.string() + "': write the scene to a .json file");
    check_outputs({{"output", out}}, {{"scene", in}});
    const PbrtConversion c = convert_pbrt(in, out, a.strict, true);
    // Every file the conversion read (Includes, spectra, meshes, images), before anything is written.
    std::vector<NamedFile> inputs;
    for (const std::filesystem::path& f : c.input_files) inputs.push_back({"scene's input", f});
    check_outputs({{"output", out}}, inputs);
    for (const std::string& w : c.warnings) std::fprintf(stderr, "sweeptrace: warning: %s\n", escape_control(w).c_str());
    write_text_file(out, c.json_text);
    if (!a.quiet)
        std::fprintf(stderr, "%s -> %s (%zu kind%s of warning)\n", in.string().c_str(), out.string().c_str(), c.warnings.size(),
                     c.warnings.size() == 1 ? "" : "s");
    return 0;
}

}  // namespace

void add_convert_command(CLI::App& app, int& exit_code) {
    auto args = std::make_shared<ConvertArgs>();
    auto* cmd = app.add_subcommand("convert", "Translate a pbrt-v4 scene (.pbrt) to our scene JSON (docs/pbrt-import.md)");
    cmd->add_option("scene", args->scene, "pbrt-v4 scene file (.pbrt)")->required();
    cmd->add_option("-o,--output", args->output, "Output scene (.json). Default: the scene's name with .json, in the current directory");
    cmd->add_flag("--strict", args->strict, "Refuse (exit 2) anything the translation would approximate or ignore");
    cmd->add_flag("--quiet", args->quiet, "No summary line (warnings are still printed)");
    cmd->callback([args, &exit_code] { exit_code = run_convert(*args); });
}

}  // namespace sweeptrace
