#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include <stb/stb_image_write.h>  // to make JPEG files; the library's implementation is in png_io.cpp

#include "image_test_support.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/image/srgb.hpp"
#include "raytracer/input_error.hpp"

using namespace sweeptrace;
using sweeptrace::testing::bitwise_equal;
using sweeptrace::testing::ScratchDir;

namespace {

Image random_image(int w, int h, float lo, float hi, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(lo, hi);
    Image image(w, h);
    for (auto& p : image.pixels) p = {u(rng), u(rng), u(rng)};
    return image;
}

// What read_image says of a file it refuses ("no error" if it reads it).
std::string message_of(const std::filesystem::path& p) {
    try {
        read_image(p);
    } catch (const InputError& e) {
        return std::string(e.what());
    }
    return std::string("no error");
}

std::string float_bytes(float v, bool little) {
    const auto bits = std::bit_cast<std::uint32_t>(v);
    std::string s(4, '\0');
    for (int b = 0; b < 4; ++b) s[little ? b : 3 - b] = static_cast<char>(bits >> (8 * b));
    return s;
}

}  // namespace

TEST_CASE("sRGB curves: exact piecewise values, inverse of each other, against long double", "[image][srgb]") {
    CHECK(srgb_encode(0.0f) == 0.0f);
    CHECK(srgb_encode(1.0f) == 1.0f);
    CHECK(srgb_encode(-1.0f) == 0.0f);
    CHECK(srgb_encode(std::nanf("")) == 0.0f);
    CHECK(srgb_encode(0.002f) == Approx(12.92f * 0.002f).epsilon(1e-7));  // linear segment
    for (int i = 1; i < 1000; ++i) {
        const long double x = i / 1000.0L;
        const long double ref = x <= 0.0031308L ? 12.92L * x : 1.055L * std::pow(x, 1.0L / 2.4L) - 0.055L;
        // Bound from srgb.hpp: one float rounding of a double result -> within 1 ulp.
        CHECK(std::abs(srgb_encode(static_cast<float>(x)) - static_cast<float>(ref)) <=
              std::nextafter(static_cast<float>(ref), 2.0f) - static_cast<float>(ref));
        const float back = srgb_decode(srgb_encode(static_cast<float>(x)));
        CHECK(std::abs(back - static_cast<float>(x)) <= 4e-7f * 2.4f);  // two roundings, slope <= 2.4/1
    }
    // Every 8-bit code survives decode + encode + rounding.
    for (int code = 0; code < 256; ++code) CHECK(to_byte(srgb_encode(srgb_decode(code / 255.0f))) == code);
}

TEST_CASE("PNG round trip: 8-bit codes exact, other values within half a code step", "[image][png]") {
    ScratchDir dir("png");
    Image exact(7, 5);
    for (std::size_t i = 0; i < exact.pixels.size(); ++i)
        exact.pixels[i] = {srgb_decode((i * 7 % 256) / 255.0f), srgb_decode((i * 13 % 256) / 255.0f),
                           srgb_decode((255 - i) / 255.0f)};
    write_image(exact, dir / "exact.png");
    CHECK(bitwise_equal(read_image(dir / "exact.png"), exact));

    const Image any = random_image(9, 4, -0.2f, 1.3f, 1);
    write_image(any, dir / "any.PNG");  // extension is case-insensitive
    const Image back = read_image(dir / "any.PNG");
    REQUIRE(back.width == 9);
    REQUIRE(back.height == 4);
    for (std::size_t i = 0; i < any.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const float encoded = srgb_encode(any.pixels[i][c]);
            CHECK(std::abs(srgb_encode(back.pixels[i][c]) - encoded) <= 0.5f / 255.0f + 1e-6f);
        }
}

TEST_CASE("PNG: empty IDAT chunks (which stb would memcpy from into a null buffer) read as the same image",
          "[image][png]") {
    ScratchDir dir("png-empty-idat");
    Image image(5, 3);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = {srgb_decode((i * 37 % 256) / 255.0f), srgb_decode((i * 11 % 256) / 255.0f), srgb_decode(128 / 255.0f)};
    write_image(image, dir / "plain.png");
    const std::string plain = sweeptrace::testing::read_file_text(dir / "plain.png");
    const std::size_t idat = plain.find("IDAT");  // the type field; the chunk starts 4 bytes before
    REQUIRE(idat != std::string::npos);
    REQUIRE(idat >= 12);
    const std::string empty_idat("\0\0\0\0IDAT\x35\xaf\x06\x1e", 12);  // length 0, type, CRC-32 of "IDAT"
    // One before the image data (the case that reached memcpy(nullptr, src, 0), fuzz_png's
    // regression-empty-first-idat.png) and one after it.
    std::string padded = plain;
    const std::size_t data_length = (std::size_t(std::uint8_t(plain[idat - 4])) << 24) |
                                    (std::size_t(std::uint8_t(plain[idat - 3])) << 16) |
                                    (std::size_t(std::uint8_t(plain[idat - 2])) << 8) | std::uint8_t(plain[idat - 1]);
    padded.insert(idat + 4 + data_length + 4, empty_idat);
    padded.insert(idat - 4, empty_idat);
    sweeptrace::testing::write_file_text(dir / "padded.png", padded);
    CHECK(padded.size() == plain.size() + 24);
    CHECK(bitwise_equal(read_image(dir / "padded.png"), read_image(dir / "plain.png")));
    CHECK(bitwise_equal(read_image(dir / "padded.png"), image));
    // Many of them (dropped in one pass), and a message after them names the file's own offset.
    std::string many = plain;
    for (int k = 0; k < 1000; ++k) many.insert(idat - 4, empty_idat);
    sweeptrace::testing::write_file_text(dir / "many.png", many);
    CHECK(bitwise_equal(read_image(dir / "many.png"), image));
    const std::size_t iend = many.rfind("IEND") - 4;
    many[iend + 3] = '\x7f';  // IEND now claims 127 bytes
    sweeptrace::testing::write_file_text(dir / "bad.png", many);
    std::string message;
    try {
        read_image(dir / "bad.png");
    } catch (const std::exception& e) {
        message = e.what();
    }
    CHECK_THAT(message, Catch::Contains("chunk at byte " + std::to_string(iend) + " claims 127 bytes"));
}

TEST_CASE("PFM round trip is bit-exact, including values a PNG cannot hold", "[image][pfm]") {
    ScratchDir dir("pfm");
    Image image = random_image(6, 3, -5.0f, 100.0f, 2);
    image.at(0, 0) = {1e-30f, 3e30f, -0.0f};
    write_image(image, dir / "a.pfm");
    CHECK(bitwise_equal(read_image(dir / "a.pfm"), image));
    // Written little-endian (negative scale), rows bottom to top.
    const std::string bytes = testing::read_file_text(dir / "a.pfm");
    REQUIRE(bytes.rfind("PF\n6 3\n-1.0\n", 0) == 0);
    CHECK(bytes.substr(12, 4) == float_bytes(image.at(0, 2).x, true));
}

TEST_CASE("PFM reader: big-endian, grey 'Pf', bottom-to-top rows", "[image][pfm]") {
    ScratchDir dir("pfm-read");
    // 1 x 2 RGB, big-endian: the first row in the file is the bottom row.
    std::string be = "PF\n1 2\n1.0\n";
    for (float v : {1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f}) be += float_bytes(v, false);
    testing::write_file_text(dir / "be.pfm", be);
    const Image a = read_image(dir / "be.pfm");
    REQUIRE(a.width == 1);
    REQUIRE(a.height == 2);
    CHECK(a.at(0, 1) == glm::vec3(1.0f, 2.0f, 3.0f));
    CHECK(a.at(0, 0) == glm::vec3(4.0f, 5.0f, 6.0f));
    // Grey, little-endian, 2 x 1, header split across arbitrary whitespace.
    testing::write_file_text(dir / "grey.pfm", "Pf  2\t1\n-2.5\n" + float_bytes(0.25f, true) + float_bytes(7.0f, true));
    const Image g = read_image(dir / "grey.pfm");
    CHECK(g.at(0, 0) == glm::vec3(0.25f));
    CHECK(g.at(1, 0) == glm::vec3(7.0f));
}

TEST_CASE("EXR round trip is exact in 32-bit float", "[image][exr]") {
    ScratchDir dir("exr");
    Image image = random_image(5, 8, 0.0f, 50.0f, 3);
    write_image(image, dir / "a.exr");
    CHECK(bitwise_equal(read_image(dir / "a.exr"), image));
}

TEST_CASE("JPEG reader: 8-bit sRGB decoded to linear, a wrong signature and a cut file refused", "[image][jpeg]") {
    // Flat 8x8 blocks survive JPEG at quality 100 up to the colour conversion's rounding, so
    // every pixel is within a few codes of what was written; the size must be exact.
    ScratchDir dir("jpeg");
    constexpr int w = 16, h = 8;
    const unsigned char codes[2][3] = {{200, 40, 90}, {10, 250, 128}};
    std::vector<unsigned char> rgb(w * h * 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) rgb[(y * w + x) * 3 + c] = codes[x / 8][c];
    const std::string file = (dir / "two.jpg").string();
    REQUIRE(stbi_write_jpg(file.c_str(), w, h, 3, rgb.data(), 100) != 0);
    const Image image = read_image(file);
    REQUIRE(image.width == w);
    REQUIRE(image.height == h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) {
                INFO("pixel " << x << "," << y << " channel " << c);
                CHECK(std::abs(srgb_encode(image.at(x, y)[c]) * 255.0f - codes[x / 8][c]) <= 3.0f);
            }
    // The same upper case; a PNG named .jpeg is refused, not decoded as PNG; a cut file fails.
    std::filesystem::copy_file(file, dir / "upper.JPG");
    CHECK(read_image(dir / "upper.JPG").width == w);
    write_image(image, dir / "png.png");
    std::filesystem::copy_file(dir / "png.png", dir / "png.jpeg");
    using Catch::Matchers::Contains;
    CHECK_THAT(message_of(dir / "png.jpeg"), Contains("png.jpeg") && Contains("no JPEG start-of-image marker"));
    const auto bytes = testing::read_file_text(file);
    testing::write_file_text(dir / "cut.jpg", bytes.substr(0, bytes.size() / 3));
    CHECK_THAT(message_of(dir / "cut.jpg"), Contains("cut.jpg") && Contains("not a valid JPEG"));
    // Outputs are never JPEG.
    CHECK_THROWS_AS(write_image(image, dir / "out.jpg"), InputError);
}

TEST_CASE("read errors name the file and what is wrong", "[image][errors]") {
    ScratchDir dir("read-errors");
    using Catch::Matchers::Contains;
    CHECK_THAT(message_of(dir / "missing.png"), Contains("missing.png") && Contains("no such file"));
    CHECK_THAT(message_of(dir / "missing.exr"), Contains("missing.exr") && Contains("no such file"));
    CHECK_THAT(message_of(dir / "a.bmp"), Contains("a.bmp") && Contains("unknown image extension"));
    testing::write_file_text(dir / "junk.png", "this is not a png");
    CHECK_THAT(message_of(dir / "junk.png"), Contains("junk.png") && Contains("not a valid PNG"));
    testing::write_file_text(dir / "junk.exr", "this is not an exr");
    CHECK_THAT(message_of(dir / "junk.exr"), Contains("junk.exr") && Contains("not a valid EXR"));
    testing::write_file_text(dir / "magic.pfm", "P6\n1 1\n255\nabc");
    CHECK_THAT(message_of(dir / "magic.pfm"), Contains("magic.pfm") && Contains("magic number"));
    testing::write_file_text(dir / "short.pfm", "PF\n2 2\n-1.0\n" + float_bytes(1.0f, true));
    CHECK_THAT(message_of(dir / "short.pfm"), Contains("short.pfm") && Contains("needs 48"));
    testing::write_file_text(dir / "size.pfm", "PF\n0 2\n-1.0\n");
    CHECK_THAT(message_of(dir / "size.pfm"), Contains("out of range"));
    testing::write_file_text(dir / "scale.pfm", "PF\n1 1\nabc\n");
    CHECK_THAT(message_of(dir / "scale.pfm"), Contains("scale 'abc' is not a number"));
    std::filesystem::create_directory(dir / "dir.png");
    CHECK_THAT(message_of(dir / "dir.png"), Contains("is a directory"));
}

TEST_CASE("a failed write leaves no file, no temporary, and an existing file untouched", "[image][atomic]") {
    ScratchDir dir("atomic");
    const Image image = random_image(4, 4, 0.0f, 1.0f, 4);
    auto entries = [&] {
        std::size_t n = 0;
        for (const auto& e : std::filesystem::directory_iterator(dir.path())) n += !e.path().empty();
        return n;
    };
    for (const char* name : {"old.png", "old.pfm", "old.exr"}) testing::write_file_text(dir / name, "precious");

    // Unknown extension: refused before anything is created.
    CHECK_THROWS_AS(write_image(image, dir / "old.tga"), InputError);
    // Missing directory, and a parent that is a file.
    CHECK_THROWS_AS(write_image(image, dir / "no-such-dir" / "a.png"), InputError);
    CHECK_THROWS_AS(write_image(image, dir / "old.png" / "a.png"), InputError);
    // The rename fails because the target is a non-empty directory: the temporary must go.
    std::filesystem::create_directories(dir / "taken.exr" / "inside");
    CHECK_THROWS_AS(write_image(image, dir / "taken.exr"), InputError);
    CHECK(std::filesystem::is_directory(dir / "taken.exr" / "inside"));
    // An image whose pixel count does not match its size is refused; the old file stays.
    Image broken(4, 4);
    broken.pixels.pop_back();
    for (const char* name : {"old.png", "old.pfm", "old.exr"}) {
        CHECK_THROWS_AS(write_image(broken, dir / name), InputError);
        CHECK(testing::read_file_text(dir / name) == "precious");
    }
    CHECK(entries() == 4);  // the three old files and taken.exr: no temporaries left behind

    // A successful write replaces the old file completely.
    write_image(image, dir / "old.pfm");
    CHECK(bitwise_equal(read_image(dir / "old.pfm"), image));
    CHECK(entries() == 4);
}
