#include "raytracer/scene/load_environment.hpp"

#include <cmath>
#include <string>

#include "raytracer/image/image.hpp"
#include "raytracer/scene/load_image_file.hpp"
#include "raytracer/scene/scene_transform.hpp"

namespace sweeptrace {

void read_environment(const scene_json::Node& node, Background& background) {
    node.require_object({"file", "rotate", "mirror", "mapping", "scale"});
    Background::EnvironmentMapping mapping = Background::EnvironmentMapping::Equirect;
    if (auto m = node.find("mapping")) {
        const std::string name = m->string();
        if (name == "equal-area") mapping = Background::EnvironmentMapping::EqualArea;
        else if (name != "equirect") m->fail("unknown mapping \"" + name + "\" (known: equirect, equal-area)");
    }
    const auto mirror = node.find("mirror");
    const bool mirrored = mirror && mirror->boolean();
    const scene_json::Node file = node.at("file");
    const std::filesystem::path name(file.string());
    if (is_8bit_srgb(name))
        file.fail("an environment must be linear radiance: use .hdr, .exr or .pfm, not an 8-bit " +
                  name.extension().string());
    const std::shared_ptr<const Image> map = read_image_file(file, "environment image");
    const Image& image = *map;
    if (image.width < 2 || image.height < 1) file.fail("environment image must be at least 2x1 pixels");
    // Equal-area texels tile a square; another shape is a layout mistake (likely a 2:1 equirect map).
    if (mapping == Background::EnvironmentMapping::EqualArea && image.width != image.height)
        file.fail("an equal-area map must be square, got " + std::to_string(image.width) + "x" +
                  std::to_string(image.height));
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            if (!(image.pixels[i][c] >= 0.0f) || !std::isfinite(image.pixels[i][c]))
                file.fail("environment image has a negative or non-finite value at pixel (" +
                          std::to_string(i % image.width) + ", " + std::to_string(i / image.width) + ")");
    background.kind = Background::Kind::Environment;
    background.environment = map;
    background.mapping = mapping;
    background.mirror = mirrored;
    if (auto r = node.find("rotate")) {
        if (r->value().is_number()) {
            background.rotate_degrees = r->number();
        } else {
            // Any turn, as a transform's rotate step: for maps whose pole is not our +Y (a z-up world).
            r->require_object({"axis", "degrees"});
            background.turned = true;
            background.turn = glm::mat3(rotation_matrix(glm::dvec3(r->at("axis").nonzero_vec3()), r->at("degrees").number()));
        }
    }
    if (auto s = node.find("scale")) background.scale = s->number_at_least(0.0f, true);
}

}  // namespace sweeptrace
