#include "raytracer/scene/load_environment.hpp"

#include <cmath>
#include <string>
#include <system_error>

#include "raytracer/input_error.hpp"

namespace sweeptrace {

void read_environment(const scene_json::Node& node, Background& background) {
    node.require_object({"file", "rotate", "scale"});
    const scene_json::Node file = node.at("file");
    const std::string relative = file.string();
    if (relative.empty()) file.fail("must name an equirectangular image (.hdr, .exr or .pfm)");
    const std::filesystem::path path = file.file().parent_path() / relative;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        file.fail("environment image \"" + relative + "\" not found (looked for " + path.string() + ")");
    const std::string ext = path.extension().string();
    if (ext == ".png" || ext == ".PNG")
        file.fail("an environment must be linear radiance: use .hdr, .exr or .pfm, not an 8-bit .png");
    Image image;
    try {
        image = read_image(path);
    } catch (const InputError& e) {
        file.fail(e.what());
    }
    if (image.width < 2 || image.height < 1) file.fail("environment image must be at least 2x1 pixels");
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            if (!(image.pixels[i][c] >= 0.0f) || !std::isfinite(image.pixels[i][c]))
                file.fail("environment image has a negative or non-finite value at pixel (" +
                          std::to_string(i % image.width) + ", " + std::to_string(i / image.width) + ")");
    background.kind = Background::Kind::Environment;
    background.environment = std::make_shared<const Image>(std::move(image));
    if (auto r = node.find("rotate")) background.rotate_degrees = r->number();
    if (auto s = node.find("scale")) background.scale = s->number_at_least(0.0f, true);
}

}  // namespace sweeptrace
