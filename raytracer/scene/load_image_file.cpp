#include "raytracer/scene/load_image_file.hpp"

#include <system_error>

#include "raytracer/input_error.hpp"
#include "raytracer/scene/read_files.hpp"

namespace sweeptrace {

std::shared_ptr<const Image> read_image_path(const std::string& relative, const std::filesystem::path& path,
                                             const std::string& what, const ImageFail& fail) {
    if (relative.empty()) fail("must name an image file");
    note_read_file(path);
    if (const std::string problem = file_kind_problem(path); !problem.empty())
        fail(what + " \"" + relative + "\" " + problem + " (looked for " + path.string() + ")");
    Image image;
    try {
        image = read_image(path);
    } catch (const InputError& e) {
        fail(e.what());
    }
    if (image.width < 1 || image.height < 1) fail(what + " is empty");
    return std::make_shared<const Image>(std::move(image));
}

std::shared_ptr<const Image> read_image_file(const scene_json::Node& file, const std::string& what) {
    const std::string relative = file.string();
    return read_image_path(relative, file.file().parent_path() / relative, what,
                           [&](const std::string& message) { file.fail(message); });
}

}  // namespace sweeptrace
