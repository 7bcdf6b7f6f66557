// JPEG through libjpeg-turbo: 8-bit sRGB, read only, for texture files (a renderer's outputs
// are never JPEG: lossy, and no float form). Not stb's decoder: under the fuzzer its Huffman
// table builder hits undefined behaviour within a few hundred inputs; libjpeg-turbo is the
// decoder every browser fuzzes.
#include <cstdio>  // jpeglib.h needs FILE and size_t declared first

#include <jpeglib.h>

#include <climits>
#include <csetjmp>
#include <string>

#include "raytracer/image/image_formats.hpp"
#include "raytracer/image/srgb.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace::formats {
namespace {

// libjpeg reports a fatal error by calling error_exit, which must not return: it jumps back
// here, and the message is thrown from C++ code with nothing of libjpeg's on the stack.
struct ErrorManager {
    jpeg_error_mgr base;
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX];
};

void on_error(j_common_ptr info) {
    auto* err = reinterpret_cast<ErrorManager*>(info->err);
    (*info->err->format_message)(info, err->message);
    std::longjmp(err->jump, 1);
}

// A corrupt-data warning (libjpeg would carry on and fill with grey) is an error here: a
// texture that decodes to something else than its file says must not render silently.
void on_message(j_common_ptr info, int level) {
    if (level < 0) on_error(info);
}

// Between setjmp and a longjmp no C++ object with a destructor may come to life in this frame
// (the jump would skip it): the row buffer is libjpeg's own (freed by jpeg_destroy), `image`
// lives in the caller. Returns what is wrong, or an empty string.
std::string decode(const std::vector<unsigned char>& bytes, const std::filesystem::path& path, Image& image) {
    jpeg_decompress_struct info{};
    ErrorManager err{};
    info.err = jpeg_std_error(&err.base);
    err.base.error_exit = on_error;
    err.base.emit_message = on_message;
    if (setjmp(err.jump)) {
        jpeg_destroy_decompress(&info);
        return err.message;
    }
    jpeg_create_decompress(&info);
    jpeg_mem_src(&info, bytes.data(), static_cast<unsigned long>(bytes.size()));
    jpeg_read_header(&info, TRUE);
    const long long w = info.image_width, h = info.image_height;
    if (!(w >= 1 && h >= 1 && w <= kMaxImageSide && h <= kMaxImageSide && w * h <= kMaxImagePixels)) {
        jpeg_destroy_decompress(&info);
        reserve_image(path, "JPEG", w, h);  // throws its message, libjpeg's state gone
    }
    info.out_color_space = JCS_RGB;
    jpeg_start_decompress(&info);
    image.width = static_cast<int>(info.output_width);
    image.height = static_cast<int>(info.output_height);
    image.pixels.assign(static_cast<std::size_t>(image.width) * image.height, glm::vec3(0.0f));
    JSAMPARRAY row = (*info.mem->alloc_sarray)(reinterpret_cast<j_common_ptr>(&info), JPOOL_IMAGE,
                                               info.output_width * 3, 1);
    const std::array<float, 256>& table = srgb_decode_table();  // a reference: nothing a longjmp skips
    while (info.output_scanline < info.output_height) {
        const int y = static_cast<int>(info.output_scanline);
        jpeg_read_scanlines(&info, row, 1);
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) image.at(x, y)[c] = table[row[0][3 * x + c]];
    }
    jpeg_finish_decompress(&info);
    jpeg_destroy_decompress(&info);
    return {};
}

}  // namespace

Image read_jpeg(const std::filesystem::path& path) {
    const std::vector<unsigned char> bytes = read_bytes(path);
    auto fail = [&](const std::string& what) {
        throw InputError("cannot read '" + path.string() + "': not a valid JPEG (" + what + ")");
    };
    if (bytes.size() > static_cast<std::size_t>(ULONG_MAX)) fail("file too large");
    if (bytes.size() < 3 || bytes[0] != 0xFF || bytes[1] != 0xD8 || bytes[2] != 0xFF) fail("no JPEG start-of-image marker");
    Image image;
    const std::string error = decode(bytes, path, image);
    if (!error.empty()) fail(error);
    return image;
}

}  // namespace sweeptrace::formats
