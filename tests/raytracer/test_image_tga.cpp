// The TGA reader (raytracer/image/tga_io.cpp): every supported type written byte by byte here
// and read back as the image its codes say (sRGB-decoded exactly like a PNG of the same codes),
// whatever the storage order; a .tga texture in a scene, as colour and as data; and each kind of
// malformed file refused with its own message, a huge header before anything is allocated.
#include <catch2/catch.hpp>

#include <array>
#include <string>
#include <vector>

#include "image_test_support.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/image/srgb.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "scene_test_files.hpp"

using namespace sweeptrace;
using Catch::Matchers::Contains;
using namespace std::string_literals;  // "\x00..."s keeps its NUL bytes

namespace {

using TgaCodes = std::array<unsigned char, 3>;  // R, G, B
using TgaRows = std::vector<std::vector<TgaCodes>>;  // top row first

// 3x2, every channel different.
const TgaRows kTgaPicture = {{{200, 40, 90}, {10, 250, 128}, {0, 0, 0}}, {{255, 255, 255}, {1, 2, 3}, {64, 128, 192}}};
// 4x2 with runs for the RLE cases: stored bottom-up, A A A B | B B C D, so one run crosses rows.
const TgaCodes kA{12, 34, 56}, kB{250, 0, 7}, kC{90, 90, 90}, kD{3, 200, 100};
const TgaRows kTgaRuns = {{kB, kB, kC, kD}, {kA, kA, kA, kB}};

std::string tga_header(int type, int w, int h, int bits, int descriptor, int id_length = 0, int map_first = 0,
                       int map_length = 0, int map_bits = 0) {
    const int map_type = map_length > 0 ? 1 : 0;
    const int fields[] = {id_length, map_type, type};
    std::string s;
    for (int f : fields) s += static_cast<char>(f);
    for (int v : {map_first, map_length}) s += {static_cast<char>(v & 255), static_cast<char>(v >> 8)};
    s += static_cast<char>(map_bits);
    s += std::string(4, '\0');  // x and y origin
    for (int v : {w, h}) s += {static_cast<char>(v & 255), static_cast<char>(v >> 8)};
    s += {static_cast<char>(bits), static_cast<char>(descriptor)};
    return s;
}

std::string tga_bgr(const TgaCodes& c) { return {static_cast<char>(c[2]), static_cast<char>(c[1]), static_cast<char>(c[0])}; }

// The picture's pixels in storage order: rows bottom-up unless top_down, each right to left if asked.
std::string tga_stored(const TgaRows& rows, bool top_down, bool right_to_left, std::string (*pixel)(const TgaCodes&)) {
    std::string s;
    const std::size_t h = rows.size(), w = rows[0].size();
    for (std::size_t r = 0; r < h; ++r)
        for (std::size_t c = 0; c < w; ++c) s += pixel(rows[top_down ? r : h - 1 - r][right_to_left ? w - 1 - c : c]);
    return s;
}

// What read_image must return for these codes: each decoded by the sRGB table, as for a PNG.
Image tga_expected(const TgaRows& rows) {
    Image image(static_cast<int>(rows[0].size()), static_cast<int>(rows.size()));
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const TgaCodes& c = rows[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)];
            image.at(x, y) = glm::vec3(srgb_decode_table()[c[0]], srgb_decode_table()[c[1]], srgb_decode_table()[c[2]]);
        }
    return image;
}

Image tga_read(const testing::ScratchDir& dir, const std::string& name, const std::string& bytes) {
    testing::write_file_text(dir / name, bytes);
    return read_image(dir / name);
}

std::string tga_message(const testing::ScratchDir& dir, const std::string& name, const std::string& bytes) {
    testing::write_file_text(dir / name, bytes);
    try {
        read_image(dir / name);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

const Material& tga_material(const Scene& s, const std::string& name) {
    for (const Material& m : s.materials)
        if (m.name == name) return m;
    FAIL("no material " << name);
    return s.materials[0];
}

}  // namespace

TEST_CASE("TGA: uncompressed 24- and 32-bit true colour in every storage order equals the PNG of its codes", "[image][tga]") {
    testing::ScratchDir dir("tga-true-colour");
    const Image expected = tga_expected(kTgaPicture);
    write_image(expected, dir / "same.png");
    REQUIRE(testing::bitwise_equal(read_image(dir / "same.png"), expected));  // PNG keeps 8-bit codes exactly

    const std::string bottom_up = tga_stored(kTgaPicture, false, false, tga_bgr);
    CHECK(testing::bitwise_equal(tga_read(dir, "bottom.tga", tga_header(2, 3, 2, 24, 0x00) + bottom_up), expected));
    CHECK(testing::bitwise_equal(tga_read(dir, "top.tga", tga_header(2, 3, 2, 24, 0x20) + tga_stored(kTgaPicture, true, false, tga_bgr)),
                        expected));
    CHECK(testing::bitwise_equal(tga_read(dir, "mirror.TGA", tga_header(2, 3, 2, 24, 0x30) + tga_stored(kTgaPicture, true, true, tga_bgr)),
                        expected));
    // 32-bit BGRA, the alpha (8 alpha bits in the descriptor) dropped whatever it is.
    std::string varied = tga_stored(kTgaPicture, false, false, [](const TgaCodes& c) { return tga_bgr(c) + "\x11"; });
    for (std::size_t i = 3; i < varied.size(); i += 4) varied[i] = static_cast<char>(i * 50);
    CHECK(testing::bitwise_equal(tga_read(dir, "alpha.tga", tga_header(2, 3, 2, 32, 0x08) + varied), expected));
    // An image ID before the pixels, and TGA 2.0's footer after them.
    const std::string id = "made by a test";
    const std::string footer = std::string(8, '\0') + "TRUEVISION-XFILE." + '\0';
    CHECK(testing::bitwise_equal(
        tga_read(dir, "id.tga", tga_header(2, 3, 2, 24, 0, static_cast<int>(id.size())) + id + bottom_up + footer), expected));
    // A colour map beside a true-colour image is skipped.
    CHECK(testing::bitwise_equal(tga_read(dir, "unused-map.tga", tga_header(2, 3, 2, 24, 0, 0, 0, 2, 24) + std::string(6, '\x7f') + bottom_up),
                        expected));
}

TEST_CASE("TGA: 16-bit 5-5-5 widens each channel to round(255 c / 31), the attribute bit dropped", "[image][tga]") {
    testing::ScratchDir dir("tga-555");
    const int five[2][3] = {{31, 0, 16}, {1, 30, 5}};
    std::string data;
    for (int i = 0; i < 2; ++i) {
        const int v = (five[i][0] << 10) | (five[i][1] << 5) | five[i][2] | (i == 1 ? 0x8000 : 0);
        data += {static_cast<char>(v & 255), static_cast<char>(v >> 8)};
    }
    TgaRows rows(1);
    for (const auto& p : five)
        rows[0].push_back({static_cast<unsigned char>((p[0] * 255 + 15) / 31), static_cast<unsigned char>((p[1] * 255 + 15) / 31),
                           static_cast<unsigned char>((p[2] * 255 + 15) / 31)});
    CHECK(rows[0][0] == TgaCodes{255, 0, 132});
    CHECK(testing::bitwise_equal(tga_read(dir, "a.tga", tga_header(2, 2, 1, 16, 0x21) + data), tga_expected(rows)));
    CHECK(testing::bitwise_equal(tga_read(dir, "b.tga", tga_header(2, 2, 1, 15, 0x20) + data), tga_expected(rows)));
}

TEST_CASE("TGA: greyscale 8-bit, and 16-bit grey then alpha", "[image][tga]") {
    testing::ScratchDir dir("tga-grey");
    const TgaRows grey = {{{7, 7, 7}, {128, 128, 128}}, {{255, 255, 255}, {0, 0, 0}}};
    const auto one = [](const TgaCodes& c) { return std::string(1, static_cast<char>(c[0])); };
    const auto with_alpha = [](const TgaCodes& c) { return std::string{static_cast<char>(c[0]), '\x42'}; };
    CHECK(testing::bitwise_equal(tga_read(dir, "g8.tga", tga_header(3, 2, 2, 8, 0) + tga_stored(grey, false, false, one)), tga_expected(grey)));
    CHECK(testing::bitwise_equal(tga_read(dir, "g16.tga", tga_header(3, 2, 2, 16, 0x28) + tga_stored(grey, true, false, with_alpha)),
                        tga_expected(grey)));
}

TEST_CASE("TGA: run-length encoded true colour and grey, runs and raw packets, a run across rows", "[image][tga]") {
    testing::ScratchDir dir("tga-rle");
    // Stored bottom-up: run of 3 A, run of 3 B (the bottom row's end and the top row's start), raw C D.
    const std::string rle = "\x82" + tga_bgr(kA) + "\x82" + tga_bgr(kB) + "\x01" + tga_bgr(kC) + tga_bgr(kD);
    CHECK(testing::bitwise_equal(tga_read(dir, "rle.tga", tga_header(10, 4, 2, 24, 0) + rle), tga_expected(kTgaRuns)));
    const std::string rle32 = "\x82" + tga_bgr(kA) + "\xff\x82" + tga_bgr(kB) + "\x00\x01"s + tga_bgr(kC) + "\x01" + tga_bgr(kD) + "\x02";
    CHECK(testing::bitwise_equal(tga_read(dir, "rle32.tga", tga_header(10, 4, 2, 32, 0x08) + rle32), tga_expected(kTgaRuns)));
    // The same picture top-down: B B C D | A A A B is a run of 2, raw 2, run of 3, raw 1.
    const std::string top = "\x81" + tga_bgr(kB) + "\x01" + tga_bgr(kC) + tga_bgr(kD) + "\x82" + tga_bgr(kA) + "\x00"s + tga_bgr(kB);
    CHECK(testing::bitwise_equal(tga_read(dir, "rle-top.tga", tga_header(10, 4, 2, 24, 0x20) + top), tga_expected(kTgaRuns)));

    const TgaRows grey = {{{9, 9, 9}, {9, 9, 9}, {200, 200, 200}}, {{1, 1, 1}, {9, 9, 9}, {9, 9, 9}}};
    // Bottom-up: 1 9 9 | 9 9 200 -> raw 1 of "1", run of 4 "9", raw 1 of "200".
    CHECK(testing::bitwise_equal(tga_read(dir, "rle-grey.tga", tga_header(11, 3, 2, 8, 0) + "\x00\x01\x83\x09\x00\xc8"s),
                        tga_expected(grey)));
}

TEST_CASE("TGA: colour-mapped, raw and RLE, with a map that starts past index 0", "[image][tga]") {
    testing::ScratchDir dir("tga-mapped");
    // Entries 5, 6, 7, 8 are A, B, C, D; 24-bit entries with 8-bit indices, 32-bit with 16-bit.
    const std::string map24 = tga_bgr(kA) + tga_bgr(kB) + tga_bgr(kC) + tga_bgr(kD);
    const std::string map32 = tga_bgr(kA) + "\x01" + tga_bgr(kB) + "\x02" + tga_bgr(kC) + "\x03" + tga_bgr(kD) + "\x04";
    const std::string indices = "\x05\x05\x05\x06\x06\x06\x07\x08";  // bottom-up
    CHECK(testing::bitwise_equal(tga_read(dir, "m8.tga", tga_header(1, 4, 2, 8, 0, 0, 5, 4, 24) + map24 + indices), tga_expected(kTgaRuns)));
    std::string wide;
    for (char i : indices) wide += {i, '\0'};
    CHECK(testing::bitwise_equal(tga_read(dir, "m16.tga", tga_header(1, 4, 2, 16, 0, 0, 5, 4, 32) + map32 + wide), tga_expected(kTgaRuns)));
    CHECK(testing::bitwise_equal(tga_read(dir, "m-rle.tga", tga_header(9, 4, 2, 8, 0, 0, 5, 4, 24) + map24 + "\x82\x05\x82\x06\x01\x07\x08"),
                        tga_expected(kTgaRuns)));
}

TEST_CASE("TGA: malformed and unsupported files are refused, each naming the file and what is wrong", "[image][tga][errors]") {
    testing::ScratchDir dir("tga-errors");
    const std::string good = tga_header(2, 3, 2, 24, 0) + tga_stored(kTgaPicture, false, false, tga_bgr);
    CHECK_THAT(tga_message(dir, "header.tga", good.substr(0, 10)),
               Contains("header.tga") && Contains("not a valid TGA file (the 18-byte header is cut off: the file has 10 bytes)"));
    CHECK_THAT(tga_message(dir, "empty.tga", ""), Contains("empty.tga") && Contains("header is cut off"));
    CHECK_THAT(tga_message(dir, "cut.tga", good.substr(0, good.size() - 1)),
               Contains("cut.tga") && Contains("3x2 pixels need 18 bytes after byte 18, the file has 17"));
    CHECK_THAT(tga_message(dir, "id.tga", tga_header(2, 1, 1, 24, 0, 200) + "abc"),
               Contains("id.tga") && Contains("the image ID of 200 bytes at byte 18 needs 200 bytes, the file has 3"));
    // RLE: a packet past the image's last pixel, and data that ends inside a raw packet.
    CHECK_THAT(tga_message(dir, "overrun.tga", tga_header(10, 2, 2, 24, 0) + "\x82" + tga_bgr(kA) + "\x81" + tga_bgr(kB)),
               Contains("overrun.tga") && Contains("the RLE packet at byte 22 runs past the image (pixels 3..4 of 4)"));
    CHECK_THAT(tga_message(dir, "rle-cut.tga", tga_header(10, 200, 1, 24, 0) + "\x7f" + std::string(3 * 100, '\x10')),
               Contains("rle-cut.tga") && Contains("pixel data ends at byte 319, at pixel 100 of 200"));
    CHECK_THAT(tga_message(dir, "rle-short.tga", tga_header(10, 200, 1, 24, 0) + "\x82" + tga_bgr(kA)),
               Contains("200x1 RLE pixels need at least 8 bytes after byte 18, the file has 4"));
    // Colour maps: an index outside it, a mapped type without one, a map cut off.
    CHECK_THAT(tga_message(dir, "index.tga", tga_header(1, 2, 1, 8, 0, 0, 5, 1, 24) + tga_bgr(kA) + "\x05\x06"),
               Contains("index.tga") && Contains("colour index 6 at pixel 1 is outside the map (5..5)"));
    CHECK_THAT(tga_message(dir, "nomap.tga", tga_header(1, 2, 1, 8, 0) + "\x00\x00"s),
               Contains("image type 1 is colour-mapped but the header gives no colour map"));
    CHECK_THAT(tga_message(dir, "mapcut.tga", tga_header(1, 2, 1, 8, 0, 0, 0, 256, 24) + "\x00\x00"s),
               Contains("the colour map of 256 entries at byte 18 needs 768 bytes, the file has 2"));
    // Unsupported: types, depths, interleaving.
    CHECK_THAT(tga_message(dir, "none.tga", tga_header(0, 1, 1, 24, 0)),
               Contains("none.tga") && Contains("unsupported TGA file (image type 0: no image data)"));
    CHECK_THAT(tga_message(dir, "huffman.tga", tga_header(32, 1, 1, 24, 0) + "abc"),
               Contains("unsupported TGA file (image type 32 (read: 1, 2, 3 and their RLE forms 9, 10, 11))"));
    CHECK_THAT(tga_message(dir, "depth.tga", tga_header(2, 1, 1, 8, 0) + "a"),
               Contains("unsupported TGA file (image type 2 with 8-bit pixels (read: 15, 16, 24, 32))"));
    CHECK_THAT(tga_message(dir, "grey24.tga", tga_header(11, 1, 1, 24, 0) + "\x00"s + "abc"),
               Contains("unsupported TGA file (image type 11 with 24-bit pixels (read: 8, 16))"));
    CHECK_THAT(tga_message(dir, "entries.tga", tga_header(1, 1, 1, 8, 0, 0, 0, 1, 8) + "\x00\x00"s),
               Contains("unsupported TGA file (8-bit colour map entries (read: 15, 16, 24, 32))"));
    // Also a map a true-colour image does not use: its entries' size places the pixels.
    CHECK_THAT(tga_message(dir, "unused-entries.tga", tga_header(2, 1, 1, 24, 0, 0, 0, 4, 0) + "abc"),
               Contains("unsupported TGA file (0-bit colour map entries (read: 15, 16, 24, 32))"));
    CHECK_THAT(tga_message(dir, "interleaved.tga", tga_header(2, 1, 1, 24, 0x40) + "abc"),
               Contains("unsupported TGA file (interleaved rows (image descriptor bits 6-7 are set))"));
}

TEST_CASE("TGA: dimensions out of range are refused from the header, before the pixels are allocated", "[image][tga][errors]") {
    testing::ScratchDir dir("tga-size");
    // 65535 x 65535 (the format's largest) is over the 2^26-pixel limit every reader applies.
    CHECK_THAT(tga_message(dir, "huge.tga", tga_header(2, 65535, 65535, 24, 0)),
               Contains("huge.tga") && Contains("TGA size 65535x65535 is out of range"));
    CHECK_THAT(tga_message(dir, "zero.tga", tga_header(2, 0, 4, 24, 0)), Contains("TGA size 0x4 is out of range"));
    // 8192 x 8192 is allowed (805 MB as an Image), but an RLE file must hold at least one 4-byte
    // packet per 128 pixels: a 22-byte file is refused by that count, not by running out of memory.
    CHECK_THAT(tga_message(dir, "claims.tga", tga_header(10, 8192, 8192, 24, 0) + "\xff" + tga_bgr(kA)),
               Contains("8192x8192 RLE pixels need at least 2097152 bytes after byte 18, the file has 4"));
}

TEST_CASE("TGA texture: a scene's .tga reads as sRGB for colours and as its codes for data, like the same .png",
          "[scene][texture][tga]") {
    test::TempDir dir;
    const TgaRows codes = {{{10, 128, 255}, {1, 254, 0}}};
    dir.write("map.tga", tga_header(2, 2, 1, 24, 0x20) + tga_stored(codes, true, false, tga_bgr));
    write_image(tga_expected(codes), dir.path() / "map.png");
    const auto scene = [&](const std::string& file) {
        return R"({ "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0] }, "film": { "width": 4, "height": 4 },
            "objects": [ { "type": "sphere", "radius": 1, "material": "m" } ],
            "materials": { "m": { "type": "metal", "albedo": { "image": { "file": ")" + file + R"(" } },
                                  "roughness": { "image": { "file": ")" + file + R"(" } } } } })";
    };
    const Scene tga = load_scene(dir.write("tga.json", scene("map.tga")));
    const Scene png = load_scene(dir.write("png.json", scene("map.png")));
    const Material &mt = tga_material(tga, "m"), &mp = tga_material(png, "m");
    const Image& colour = *tga.textures[static_cast<std::size_t>(mt.albedo_texture)].image;
    const Image& data = *tga.textures[static_cast<std::size_t>(mt.roughness_texture)].image;
    CHECK(testing::bitwise_equal(colour, tga_expected(codes)));
    CHECK(data.pixels[0] == glm::vec3(10.0f / 255.0f, 128.0f / 255.0f, 1.0f));
    CHECK(data.pixels[1] == glm::vec3(1.0f / 255.0f, 254.0f / 255.0f, 0.0f));
    CHECK(testing::bitwise_equal(colour, *png.textures[static_cast<std::size_t>(mp.albedo_texture)].image));
    CHECK(testing::bitwise_equal(data, *png.textures[static_cast<std::size_t>(mp.roughness_texture)].image));
}
