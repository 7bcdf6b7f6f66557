#include "raytracer/scene/load_environment.hpp"

#include <cmath>
#include <string>

#include "raytracer/image/image.hpp"
#include "raytracer/scene/load_image_file.hpp"

namespace sweeptrace {

void read_environment(const scene_json::Node& node, Background& background) {
    node.require_object({"file", "rotate", "scale"});
    const scene_json::Node file = node.at("file");
    const std::filesystem::path name(file.string());
    if (is_8bit_srgb(name))
        file.fail("an environment must be linear radiance: use .hdr, .exr or .pfm, not an 8-bit " +
                  name.extension().string());
    const std::shared_ptr<const Image> map = read_image_file(file, "environment image");
    const Image& image = *map;
    if (image.width < 2 || image.height < 1) file.fail("environment image must be at least 2x1 pixels");
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            if (!(image.pixels[i][c] >= 0.0f) || !std::isfinite(image.pixels[i][c]))
                file.fail("environment image has a negative or non-finite value at pixel (" +
                          std::to_string(i % image.width) + ", " + std::to_string(i / image.width) + ")");
    background.kind = Background::Kind::Environment;
    background.environment = map;
    if (auto r = node.find("rotate")) background.rotate_degrees = r->number();
    if (auto s = node.find("scale")) background.scale = s->number_at_least(0.0f, true);
}

}  // namespace sweeptrace
