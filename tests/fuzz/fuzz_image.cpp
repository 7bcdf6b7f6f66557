// libFuzzer: bytes -> read_image("input.EXT") -> an Image of the size it claims, or an
// InputError. Built once per reader: FUZZ_IMAGE_EXT is "png", "pfm", "exr", "jpg", "hdr" or "tga"
// (project/CMakeLists.txt).
#include <cstdlib>

#include "fuzz_input_file.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/input_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto path = sweeptrace::fuzz::input_file("input." FUZZ_IMAGE_EXT, data, size);
    try {
        const sweeptrace::Image image = sweeptrace::read_image(path);
        if (image.width < 1 || image.height < 1 ||
            image.pixels.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
            std::abort();
    } catch (const sweeptrace::InputError&) {
    }
    return 0;
}
