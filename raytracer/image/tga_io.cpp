// Truevision TGA, read only, for textures (Bitterli's scenes in their pbrt-v4 form use it for
// nearly every textured material): 8-bit codes are sRGB, decoded to linear like a PNG's.
//
// A reader of our own, not stb_image's TGA decoder (Debian 12's stb 2.27, whose PNG decoder
// png_io.cpp compiles). stb reads past the end of a cut file as zero bytes, so a truncated TGA
// decodes to black rows without an error; it maps a colour index outside the map to entry 0,
// drops the rest of an RLE packet that runs past the image, skips the colour map's first-entry
// index as a count of bytes, and ignores the right-to-left bit. TGA has no signature, so no
// header check of stb's can tell a TGA from other bytes. The format is small (an 18-byte header,
// the image ID, an optional colour map, then pixels, raw or run-length encoded): this file checks
// every count against the bytes that are there before it allocates, names the byte or pixel of
// every error, and is fuzzed (tests/fuzz, harness tga).
//
// Read: image types 2 (true colour: 15/16-bit 5-5-5, 24-bit BGR, 32-bit BGRA), 3 (grey: 8-bit, or
// 16-bit grey then alpha, as GIMP writes it), 1 (colour-mapped: 8- or 16-bit indices into a map
// of 15/16/24/32-bit entries) and their run-length encoded forms 10, 11, 9. Rows are stored
// bottom-up unless descriptor bit 5 says top-down, and right to left when bit 4 says so; the
// image's origin fields (a screen position) are ignored. Alpha and the 5-5-5 attribute bit are
// dropped: the Image is RGB. A 5-bit channel c becomes the 8-bit code round(255 c / 31). RLE
// packets may cross rows (TGA 2.0 forbids it; writers do it). Bytes after the pixels (TGA 2.0's
// extension area and footer) are not read.
//
// Memory: check_image_size (the limit every reader applies) on the header's dimensions, then
// the bytes after the colour map must be able to hold the image: w h bytes-per-pixel when raw;
// with RLE, ceil(w h / 128) packets of at least 1 + bytes-per-pixel. So an N-byte file never
// allocates more than 128 N / 2 pixels, and a 100-byte header cannot claim 8192 x 8192.
//
// Throws InputError "cannot read '<file>': not a valid TGA file (<what>)" when the header is cut
// off or inconsistent, the ID, colour map or pixel data ends before its size (the byte or pixel
// where), an RLE packet runs past the image, or a colour index lies outside the map;
// "...: unsupported TGA file (<what>)" for image type 0 (no image) and other types, bit depths
// not listed above, and interleaved rows; check_image_size's message for the dimensions.
#include <array>
#include <string>

#include "raytracer/image/image_formats.hpp"
#include "raytracer/image/srgb.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace::formats {
namespace {

constexpr std::size_t kTgaHeaderBytes = 18;
constexpr std::size_t kTgaMaxPacket = 128;  // pixels in one RLE packet: 1 + the low 7 bits

using TgaRgb = std::array<unsigned char, 3>;  // 8-bit sRGB codes

struct TgaHeader {
    int id_length = 0, map_type = 0, type = 0;
    int map_first = 0, map_length = 0, map_bits = 0;
    int width = 0, height = 0, pixel_bits = 0, descriptor = 0;
    bool rle() const { return type >= 9; }
    bool mapped() const { return type == 1 || type == 9; }
    bool grey() const { return type == 3 || type == 11; }
    std::size_t pixel_bytes() const { return (static_cast<std::size_t>(pixel_bits) + 7) / 8; }
    std::size_t pixels() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
};

// The file's bytes with a read position; every read is checked against the end.
class TgaBytes {
public:
    TgaBytes(const std::vector<unsigned char>& bytes, const std::filesystem::path& path) : bytes_(bytes), path_(path) {}

    [[noreturn]] void fail(const std::string& what) const {
        throw InputError("cannot read '" + path_.string() + "': not a valid TGA file (" + what + ")");
    }
    [[noreturn]] void unsupported(const std::string& what) const {
        throw InputError("cannot read '" + path_.string() + "': unsupported TGA file (" + what + ")");
    }
    std::size_t at() const { return at_; }
    std::size_t left() const { return bytes_.size() - at_; }
    int u8(std::size_t i) const { return bytes_[i]; }
    int u16(std::size_t i) const { return bytes_[i] | (bytes_[i + 1] << 8); }
    // `n` bytes from the read position; `what` names them if the file ends first.
    const unsigned char* take(std::size_t n, const std::string& what) {
        if (left() < n)
            fail(what + " at byte " + std::to_string(at_) + " needs " + std::to_string(n) + " bytes, the file has " +
                 std::to_string(left()));
        at_ += n;
        return bytes_.data() + (at_ - n);
    }
    // The same without building a message per pixel: the caller names the pixel when it fails.
    const unsigned char* take_or_null(std::size_t n) {
        if (left() < n) return nullptr;
        at_ += n;
        return bytes_.data() + (at_ - n);
    }

private:
    const std::vector<unsigned char>& bytes_;
    const std::filesystem::path& path_;
    std::size_t at_ = 0;
};

// The 18 header bytes, and the types and depths this reader decodes.
TgaHeader read_tga_header(TgaBytes& in) {
    if (in.left() < kTgaHeaderBytes)
        in.fail("the 18-byte header is cut off: the file has " + std::to_string(in.left()) + " bytes");
    TgaHeader h;
    h.id_length = in.u8(0), h.map_type = in.u8(1), h.type = in.u8(2);
    h.map_first = in.u16(3), h.map_length = in.u16(5), h.map_bits = in.u8(7);
    h.width = in.u16(12), h.height = in.u16(14), h.pixel_bits = in.u8(16), h.descriptor = in.u8(17);
    in.take(kTgaHeaderBytes, "header");
    const std::string type = "image type " + std::to_string(h.type);
    const std::string depth = std::to_string(h.pixel_bits) + "-bit pixels";
    if (h.type == 0) in.unsupported("image type 0: no image data");
    if (h.type != 1 && h.type != 2 && h.type != 3 && h.type != 9 && h.type != 10 && h.type != 11)
        in.unsupported(type + " (read: 1, 2, 3 and their RLE forms 9, 10, 11)");
    if (h.map_type > 1) in.unsupported("colour map type " + std::to_string(h.map_type) + " (read: 0 none, 1 a map)");
    if (h.mapped() && h.map_type != 1) in.fail(type + " is colour-mapped but the header gives no colour map");
    // Checked for a map the image does not use too: its entry size says where the pixels start.
    if (h.map_type == 1 && h.map_bits != 15 && h.map_bits != 16 && h.map_bits != 24 && h.map_bits != 32)
        in.unsupported(std::to_string(h.map_bits) + "-bit colour map entries (read: 15, 16, 24, 32)");
    if (h.mapped()) {
        if (h.map_length == 0) in.fail("the colour map has 0 entries");
        if (h.pixel_bits != 8 && h.pixel_bits != 16) in.unsupported(type + " with " + depth + " (read: 8, 16)");
    } else if (h.grey()) {
        if (h.pixel_bits != 8 && h.pixel_bits != 16) in.unsupported(type + " with " + depth + " (read: 8, 16)");
    } else if (h.pixel_bits != 15 && h.pixel_bits != 16 && h.pixel_bits != 24 && h.pixel_bits != 32) {
        in.unsupported(type + " with " + depth + " (read: 15, 16, 24, 32)");
    }
    if ((h.descriptor & 0xC0) != 0) in.unsupported("interleaved rows (image descriptor bits 6-7 are set)");
    return h;
}

unsigned char tga_widen5(int c) { return static_cast<unsigned char>((c * 255 + 15) / 31); }

// One stored colour of `bits` bits (a pixel or a map entry, BGR order) as RGB codes.
TgaRgb tga_colour(const unsigned char* p, int bits, bool grey) {
    if (grey) return {p[0], p[0], p[0]};  // 16-bit grey: alpha in p[1], dropped
    if (bits == 15 || bits == 16) {
        const int v = p[0] | (p[1] << 8);
        return {tga_widen5((v >> 10) & 31), tga_widen5((v >> 5) & 31), tga_widen5(v & 31)};
    }
    return {p[2], p[1], p[0]};
}

// The colour map (of a colour-mapped image; another type's map is skipped) as RGB codes.
std::vector<TgaRgb> read_tga_map(TgaBytes& in, const TgaHeader& h) {
    std::vector<TgaRgb> map;
    if (h.map_type != 1) return map;
    const std::size_t entry = (static_cast<std::size_t>(h.map_bits) + 7) / 8;
    const unsigned char* p = in.take(entry * static_cast<std::size_t>(h.map_length),
                                     "the colour map of " + std::to_string(h.map_length) + " entries");
    if (!h.mapped()) return map;
    map.reserve(static_cast<std::size_t>(h.map_length));
    for (int i = 0; i < h.map_length; ++i) map.push_back(tga_colour(p + entry * static_cast<std::size_t>(i), h.map_bits, false));
    return map;
}

// Decodes stored pixels into the image: the storage order (rows bottom-up or top-down, each left
// to right or right to left) resolved once, here.
class TgaPixels {
public:
    TgaPixels(TgaBytes& in, const TgaHeader& h, const std::vector<TgaRgb>& map, Image& image)
        : in_(in), h_(h), map_(map), image_(image), bytes_(h.pixel_bytes()), count_(h.pixels()) {}

    void decode() {
        if (h_.rle()) decode_rle();
        else
            for (std::size_t i = 0; i < count_; ++i) put(i, colour(i, next(i)));
    }

private:
    const unsigned char* next(std::size_t i) {
        const unsigned char* p = in_.take_or_null(bytes_);
        if (!p)
            in_.fail("pixel data ends at byte " + std::to_string(in_.at()) + ", at pixel " + std::to_string(i) + " of " +
                     std::to_string(count_));
        return p;
    }
    TgaRgb colour(std::size_t i, const unsigned char* p) const {
        if (!h_.mapped()) return tga_colour(p, h_.pixel_bits, h_.grey());
        const int index = bytes_ == 1 ? p[0] : (p[0] | (p[1] << 8));
        if (index < h_.map_first || index - h_.map_first >= h_.map_length)
            in_.fail("colour index " + std::to_string(index) + " at pixel " + std::to_string(i) + " is outside the map (" +
                     std::to_string(h_.map_first) + ".." + std::to_string(h_.map_first + h_.map_length - 1) + ")");
        return map_[static_cast<std::size_t>(index - h_.map_first)];
    }
    void put(std::size_t i, const TgaRgb& rgb) {
        const int row = static_cast<int>(i / static_cast<std::size_t>(h_.width));
        const int column = static_cast<int>(i % static_cast<std::size_t>(h_.width));
        const int x = (h_.descriptor & 0x10) ? h_.width - 1 - column : column;
        const int y = (h_.descriptor & 0x20) ? row : h_.height - 1 - row;
        image_.at(x, y) = glm::vec3(table_[rgb[0]], table_[rgb[1]], table_[rgb[2]]);
    }
    void decode_rle() {
        for (std::size_t i = 0; i < count_;) {
            const std::size_t packet_at = in_.at();
            const unsigned char* head = in_.take_or_null(1);
            if (!head)
                in_.fail("RLE data ends at byte " + std::to_string(packet_at) + ", at pixel " + std::to_string(i) + " of " +
                         std::to_string(count_));
            const std::size_t n = (head[0] & 0x7Fu) + 1;
            if (n > count_ - i)
                in_.fail("the RLE packet at byte " + std::to_string(packet_at) + " runs past the image (pixels " +
                         std::to_string(i) + ".." + std::to_string(i + n - 1) + " of " + std::to_string(count_) + ")");
            if (head[0] & 0x80) {
                const TgaRgb rgb = colour(i, next(i));
                for (std::size_t k = 0; k < n; ++k) put(i + k, rgb);
            } else {
                for (std::size_t k = 0; k < n; ++k) put(i + k, colour(i + k, next(i + k)));
            }
            i += n;
        }
    }

    TgaBytes& in_;
    const TgaHeader& h_;
    const std::vector<TgaRgb>& map_;
    Image& image_;
    const std::size_t bytes_, count_;
    const std::array<float, 256>& table_ = srgb_decode_table();
};

}  // namespace

Image read_tga(const std::filesystem::path& path) {
    const std::vector<unsigned char> bytes = read_bytes(path);
    TgaBytes in(bytes, path);
    const TgaHeader h = read_tga_header(in);
    reserve_image(path, "TGA", h.width, h.height);
    in.take(static_cast<std::size_t>(h.id_length), "the image ID of " + std::to_string(h.id_length) + " bytes");
    const std::vector<TgaRgb> map = read_tga_map(in, h);
    const std::size_t n = h.pixels(), per = h.pixel_bytes();
    const std::size_t need = h.rle() ? (n + kTgaMaxPacket - 1) / kTgaMaxPacket * (1 + per) : n * per;
    if (in.left() < need)
        in.fail(std::to_string(h.width) + "x" + std::to_string(h.height) +
                (h.rle() ? " RLE pixels need at least " : " pixels need ") + std::to_string(need) + " bytes after byte " +
                std::to_string(in.at()) + ", the file has " + std::to_string(in.left()));
    Image image(h.width, h.height);
    TgaPixels(in, h, map, image).decode();
    return image;
}

}  // namespace sweeptrace::formats
