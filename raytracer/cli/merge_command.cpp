// `sweeptrace merge PART... -o final.png|.exr|.pfm`: farm parts (`render --samples A:B`) summed
// into the image one machine's `render --spp N` gives, bit for bit (an adaptive render's too:
// each pixel's mean over its count summed from the parts). Parts of different renders,
// overlapping ranges or missing samples exit 2 naming what is wrong; nothing is written then.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "raytracer/cli/aov_outputs.hpp"
#include "raytracer/cli/commands.hpp"
#include "raytracer/cli/memory_budget.hpp"
#include "raytracer/cli/output_guard.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/image/partial_image.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/render/film/tone_map.hpp"

namespace sweeptrace {
namespace {

struct MergeArgs {
    std::vector<std::string> parts;
    std::string output;
    bool quiet = false;
};

int run_merge(const MergeArgs& a) {
    // A bad output name fails before gigabytes of parts are read.
    std::string ext = std::filesystem::path(a.output).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext != ".png" && ext != ".exr" && ext != ".pfm")
        throw InputError("output '" + a.output + "': unknown image extension '" + ext + "' (use .png, .pfm or .exr)");
    std::vector<NamedFile> inputs;
    for (const std::string& p : a.parts) inputs.push_back({"part", p});
    check_outputs({{"output", a.output}}, inputs);
    // Headers first, so a wrong set of parts is refused before any sums are read; then one part's
    // sums at a time, so memory stays two parts' worth however many there are (estimated from the
    // size the headers declare before the first is read).
    std::vector<PartialImage> headers;
    headers.reserve(a.parts.size());
    for (const std::string& p : a.parts) headers.push_back(read_partial_header(p));
    const std::vector<std::size_t> order = check_partials(headers, a.parts);
    const RenderIdentity& id = headers[order[0]].id;
    check_merge_memory(id.width, id.height, id.adaptive != "off", id.aovs == "on", a.parts[order[0]]);
    PartialImage whole;
    whole.id = headers[order[0]].id;
    if (whole.id.aovs == "on") {  // the feature side files join the output rule
        std::vector<NamedFile> outputs{{"output", a.output}};
        add_aov_outputs(outputs, a.output);
        check_outputs(outputs, inputs);
    }
    for (std::size_t i : order) {
        const PartialImage part = read_partial(a.parts[i]);
        if (part.id != headers[i].id || part.sample_begin != headers[i].sample_begin ||
            part.sample_end != headers[i].sample_end)
            throw InputError("'" + a.parts[i] + "' changed while the merge was reading it");
        add_part(whole, part, a.parts[i]);
    }
    whole.sample_end = whole.id.spp;
    const Image image = whole.mean();
    const Image written = is_display_format(a.output) ? to_display(image) : image;
    // Parts rendered with feature outputs: the merged features too, as render writes them.
    if (whole.id.aovs == "on") write_image_with_aovs(written, whole.features, whole.id.spp, a.output);
    else write_image(written, a.output);
    if (!a.quiet)
        std::fprintf(stderr, "merge: %zu parts, %dx%d, %d spp%s -> %s\n", headers.size(), whole.id.width, whole.id.height,
                     whole.id.spp, whole.id.adaptive == "off" ? "" : " adaptive (mean)", a.output.c_str());
    return 0;
}

}  // namespace

void add_merge_command(CLI::App& app, int& exit_code) {
    auto args = std::make_shared<MergeArgs>();
    auto* cmd = app.add_subcommand("merge", "Sum farm parts (render --samples A:B) into the whole render's image");
    cmd->add_option("parts", args->parts, "Part files (.exr) of one render, covering its samples once each")->required();
    cmd->add_option("-o,--output", args->output, "Output image: .png (8-bit sRGB), .pfm or .exr (linear float)")
        ->required();
    cmd->add_flag("--quiet", args->quiet, "No summary line");
    cmd->callback([args, &exit_code] { exit_code = run_merge(*args); });
}

}  // namespace sweeptrace
