// PNG through stb: 8-bit sRGB on write, 8- or 16-bit (any channel count) on read.
// The only file that compiles stb's implementations, PNG only: .hdr is decoded by hdr_io.cpp,
// JPEG by libjpeg-turbo (jpeg_io.cpp). stb_image_write's JPEG encoder is what the tests use to
// make JPEG files.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <array>
#include <climits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "raytracer/image/image_formats.hpp"
#include "raytracer/image/srgb.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace::formats {
namespace {

void append_to_vector(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<unsigned char>*>(context);
    const auto* bytes = static_cast<const unsigned char*>(data);
    out->insert(out->end(), bytes, bytes + size);
}

// stb trusts each chunk's length field: one chunk claiming 2 GB in a 71-byte file makes it
// reallocate its buffer to 2 GB before reading (found by tests/fuzz/fuzz_png). So the chunk
// structure is walked first: every chunk must fit in what the file holds.
// And stb copies an IDAT chunk into its data buffer with memcpy even when the chunk is empty
// and no buffer exists yet, memcpy(nullptr, src, 0): undefined behaviour (found by fuzz_png,
// UBSan's nonnull-attribute check), which lets the compiler assume the buffer non-null after
// it. An empty IDAT adds no image data, so the walk also drops those chunks from the bytes stb
// decodes; the image is the same.
std::vector<unsigned char> checked_chunks(std::vector<unsigned char> bytes, const std::filesystem::path& path) {
    static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    auto fail = [&](const std::string& what) {
        throw InputError("cannot read '" + path.string() + "': not a valid PNG (" + what + ")");
    };
    if (bytes.size() < 8 || !std::equal(kSignature, kSignature + 8, bytes.begin())) fail("no PNG signature");
    // Kept chunks are moved down over dropped ones as the walk goes (one pass, whatever the
    // number of empty chunks), while `at` stays the file's own offset for the messages.
    std::size_t at = 8, kept = 8;
    while (at < bytes.size()) {
        if (bytes.size() - at < 12) fail("chunk at byte " + std::to_string(at) + " is cut off");
        const std::size_t length = (std::size_t(bytes[at]) << 24) | (std::size_t(bytes[at + 1]) << 16) |
                                   (std::size_t(bytes[at + 2]) << 8) | std::size_t(bytes[at + 3]);
        const bool end = std::equal(bytes.begin() + at + 4, bytes.begin() + at + 8, "IEND");
        if (length > bytes.size() - at - 12)
            fail("chunk at byte " + std::to_string(at) + " claims " + std::to_string(length) + " bytes, the file has " +
                 std::to_string(bytes.size() - at - 12) + " left");
        const std::size_t next = at + 12 + length;
        if (length != 0 || !std::equal(bytes.begin() + at + 4, bytes.begin() + at + 8, "IDAT")) {
            if (kept != at)
                std::copy(bytes.begin() + static_cast<std::ptrdiff_t>(at), bytes.begin() + static_cast<std::ptrdiff_t>(next),
                          bytes.begin() + static_cast<std::ptrdiff_t>(kept));
            kept += next - at;
        }
        at = next;
        if (end) {
            if (kept != at) {  // the bytes after IEND as they were
                std::copy(bytes.begin() + static_cast<std::ptrdiff_t>(at), bytes.end(),
                          bytes.begin() + static_cast<std::ptrdiff_t>(kept));
                bytes.resize(bytes.size() - (at - kept));
            }
            return bytes;
        }
    }
    fail("no IEND chunk");
    return bytes;  // not reached: fail throws
}

struct StbFree {
    void operator()(void* p) const { stbi_image_free(p); }
};

}  // namespace

void write_png(const Image& image, const std::filesystem::path& path) {
    if (image.width <= 0 || image.height <= 0 || image.width > INT_MAX / 3)
        throw InputError("cannot write '" + path.string() + "': image is " + std::to_string(image.width) + "x" +
                         std::to_string(image.height));
    std::vector<unsigned char> rgb(image.pixels.size() * 3);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) rgb[3 * i + c] = to_byte(srgb_encode(image.pixels[i][c]));
    std::vector<unsigned char> encoded;
    if (!stbi_write_png_to_func(append_to_vector, &encoded, image.width, image.height, 3, rgb.data(),
                                image.width * 3))
        throw InputError("cannot write '" + path.string() + "': PNG encoding failed");
    write_bytes(path, encoded.data(), encoded.size());
}

Image read_png(const std::filesystem::path& path) {
    std::vector<unsigned char> file = read_bytes(path);
    if (file.size() > static_cast<std::size_t>(INT_MAX))
        throw InputError("cannot read '" + path.string() + "': file too large");
    const std::vector<unsigned char> bytes = checked_chunks(std::move(file), path);
    const auto* data = bytes.data();
    const int size = static_cast<int>(bytes.size());
    int w = 0, h = 0, channels = 0;
    if (!stbi_info_from_memory(data, size, &w, &h, &channels))
        throw InputError("cannot read '" + path.string() + "': not a valid PNG (" +
                         reason_or(stbi_failure_reason(), "unreadable header") + ")");
    reserve_image(path, "PNG", w, h);
    const bool sixteen = stbi_is_16_bit_from_memory(data, size) != 0;
    Image image;
    if (sixteen) {
        std::unique_ptr<stbi_us, StbFree> px(stbi_load_16_from_memory(data, size, &w, &h, &channels, 3));
        if (!px) throw InputError("cannot read '" + path.string() + "': not a valid PNG (" + reason_or(stbi_failure_reason(), "decoding failed") + ")");
        image = Image(w, h);
        for (std::size_t i = 0; i < image.pixels.size(); ++i)
            for (int c = 0; c < 3; ++c) image.pixels[i][c] = srgb_decode(px.get()[3 * i + c] / 65535.0f);
    } else {
        std::unique_ptr<stbi_uc, StbFree> px(stbi_load_from_memory(data, size, &w, &h, &channels, 3));
        if (!px) throw InputError("cannot read '" + path.string() + "': not a valid PNG (" + reason_or(stbi_failure_reason(), "decoding failed") + ")");
        const std::array<float, 256>& table = srgb_decode_table();
        image = Image(w, h);
        for (std::size_t i = 0; i < image.pixels.size(); ++i)
            for (int c = 0; c < 3; ++c) image.pixels[i][c] = table[px.get()[3 * i + c]];
    }
    return image;
}

}  // namespace sweeptrace::formats
