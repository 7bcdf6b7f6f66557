// Portable Float Map: "PF" (RGB) or "Pf" (grey), width, height, scale (negative = little-endian,
// its magnitude unused), one whitespace byte, then 32-bit floats with rows bottom to top.
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "raytracer/image/image_formats.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace::formats {
namespace {

std::uint32_t byte_swap(std::uint32_t v) {
    return (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
}

class HeaderReader {
public:
    HeaderReader(const std::vector<unsigned char>& bytes, const std::filesystem::path& path)
        : bytes_(bytes), path_(path) {}

    // Next whitespace-separated token; leaves pos_ on the byte just after it.
    std::string token(const char* what) {
        while (pos_ < bytes_.size() && std::isspace(bytes_[pos_])) ++pos_;
        std::string t;
        while (pos_ < bytes_.size() && !std::isspace(bytes_[pos_]) && t.size() < 64) t += char(bytes_[pos_++]);
        if (t.empty()) fail(std::string("header ends before the ") + what);
        return t;
    }

    long long integer(const char* what) {
        return parsed<long long>(what, "an integer", [](const std::string& t, std::size_t* used) { return std::stoll(t, used); });
    }

    double number(const char* what) {
        return parsed<double>(what, "a number", [](const std::string& t, std::size_t* used) { return std::stod(t, used); });
    }

    // The single whitespace byte that ends the header.
    std::size_t data_start() {
        if (pos_ >= bytes_.size() || !std::isspace(bytes_[pos_])) fail("no whitespace byte after the scale");
        return pos_ + 1;
    }

    [[noreturn]] void fail(const std::string& what) const {
        throw InputError("cannot read '" + path_.string() + "': not a valid PFM file: " + what);
    }

private:
    // The next token, parsed whole by `parse` (std::stoll/stod style), or a message saying what it is not.
    template <class T, class Parse>
    T parsed(const char* what, const char* kind, Parse parse) {
        const std::string t = token(what);
        std::size_t used = 0;
        T v{};
        try {
            v = parse(t, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != t.size()) fail(std::string("the ") + what + " '" + t + "' is not " + kind);
        return v;
    }

    const std::vector<unsigned char>& bytes_;
    const std::filesystem::path& path_;
    std::size_t pos_ = 0;
};

}  // namespace

void write_pfm(const Image& image, const std::filesystem::path& path) {
    if (image.width <= 0 || image.height <= 0)
        throw InputError("cannot write '" + path.string() + "': image is " + std::to_string(image.width) + "x" +
                         std::to_string(image.height));
    const std::string header = "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
    std::vector<unsigned char> out(header.begin(), header.end());
    out.reserve(header.size() + image.pixels.size() * 12);
    for (int y = image.height - 1; y >= 0; --y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) {
                std::uint32_t bits = std::bit_cast<std::uint32_t>(image.at(x, y)[c]);
                if constexpr (std::endian::native == std::endian::big) bits = byte_swap(bits);
                for (int b = 0; b < 4; ++b) out.push_back(static_cast<unsigned char>(bits >> (8 * b)));
            }
    write_bytes(path, out.data(), out.size());
}

Image read_pfm(const std::filesystem::path& path) {
    const std::vector<unsigned char> bytes = read_bytes(path);
    HeaderReader header(bytes, path);
    const std::string magic = header.token("magic number");
    if (magic != "PF" && magic != "Pf") header.fail("magic number is '" + magic + "', expected 'PF' or 'Pf'");
    const int channels = magic == "PF" ? 3 : 1;
    const long long w = header.integer("width");
    const long long h = header.integer("height");
    reserve_image(path, "PFM", w, h);
    const double scale = header.number("scale");
    if (scale == 0.0 || !std::isfinite(scale)) header.fail("scale must be a non-zero number (its sign is the byte order)");
    const bool little = scale < 0.0;
    const std::size_t start = header.data_start();
    const std::size_t expected = static_cast<std::size_t>(w) * h * channels * 4;
    if (bytes.size() - start < expected)
        header.fail("pixel data is " + std::to_string(bytes.size() - start) + " bytes, " + std::to_string(w) + "x" +
                    std::to_string(h) + " needs " + std::to_string(expected));
    Image image(static_cast<int>(w), static_cast<int>(h));
    const unsigned char* p = bytes.data() + start;
    for (int y = image.height - 1; y >= 0; --y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < channels; ++c, p += 4) {
                std::uint32_t bits = 0;
                for (int b = 0; b < 4; ++b) bits |= std::uint32_t(p[b]) << (little ? 8 * b : 8 * (3 - b));
                const float v = std::bit_cast<float>(bits);
                if (channels == 1)
                    image.at(x, y) = glm::vec3(v);
                else
                    image.at(x, y)[c] = v;
            }
    return image;
}

}  // namespace sweeptrace::formats
