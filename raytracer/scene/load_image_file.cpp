#include "raytracer/scene/load_image_file.hpp"

#include <system_error>

#include "raytracer/input_error.hpp"

namespace sweeptrace {

std::shared_ptr<const Image> read_image_file(const scene_json::Node& file, const std::string& what) {
    const std::string relative = file.string();
    if (relative.empty()) file.fail("must name an image file");
    const std::filesystem::path path = file.file().parent_path() / relative;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        file.fail(what + " \"" + relative + "\" not found (looked for " + path.string() + ")");
    Image image;
    try {
        image = read_image(path);
    } catch (const InputError& e) {
        file.fail(e.what());
    }
    if (image.width < 1 || image.height < 1) file.fail(what + " is empty");
    return std::make_shared<const Image>(std::move(image));
}

}  // namespace sweeptrace
