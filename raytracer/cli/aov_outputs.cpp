#include "raytracer/cli/aov_outputs.hpp"

#include "raytracer/image/feature_exr.hpp"

namespace sweeptrace {

namespace {

std::filesystem::path beside(const std::filesystem::path& out, const char* what) {
    std::filesystem::path p = out;
    return p.replace_filename(out.stem().string() + "." + what + ".pfm");
}

}  // namespace

std::vector<std::filesystem::path> aov_side_files(const std::filesystem::path& out) {
    if (lowercase_extension(out) == ".exr") return {};
    return {beside(out, "albedo"), beside(out, "normal"), beside(out, "depth")};
}

void add_aov_outputs(std::vector<NamedFile>& outputs, const std::filesystem::path& out) {
    for (const std::filesystem::path& side : aov_side_files(out)) outputs.push_back({"--aovs side file", side});
}

void write_image_with_aovs(const Image& image, const std::vector<FeatureSums>& sums, int spp, const std::filesystem::path& out) {
    if (lowercase_extension(out) == ".exr") {
        write_feature_exr(sums, image.width, image.height, spp, out);
        return;
    }
    write_image(image, out);
    const FeatureLayers layers = feature_layers(sums, image.width, image.height);
    const std::vector<std::filesystem::path> sides = aov_side_files(out);
    Image depth(layers.width, layers.height);
    for (std::size_t i = 0; i < depth.pixels.size(); ++i) depth.pixels[i] = glm::vec3(layers.position.pixels[i].z);
    write_image(layers.albedo, sides[0]);
    write_image(layers.normal, sides[1]);
    write_image(depth, sides[2]);
}

}  // namespace sweeptrace
