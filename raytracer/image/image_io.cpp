// write_image / read_image: the format is the file's extension (case-insensitive).
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

#include "raytracer/image/atomic_file.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/image/image_formats.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/load_budget.hpp"

namespace sweeptrace {
namespace {

enum class Format { Png, Pfm, Exr, Hdr, Jpeg, Tga };

Format format_of(const std::filesystem::path& path, const char* verb) {
    const std::string ext = lowercase_extension(path);
    if (ext == ".png") return Format::Png;
    if (ext == ".pfm") return Format::Pfm;
    if (ext == ".exr") return Format::Exr;
    const bool read = std::string(verb) == "read";
    if (ext == ".hdr" && read) return Format::Hdr;
    if ((ext == ".jpg" || ext == ".jpeg") && read) return Format::Jpeg;
    if (ext == ".tga" && read) return Format::Tga;
    throw InputError(std::string("cannot ") + verb + " '" + path.string() + "': unknown image extension '" + ext +
                     (read ? "' (use .png, .jpg, .tga, .pfm, .exr or .hdr)" : "' (use .png, .pfm or .exr)"));
}

}  // namespace

std::string lowercase_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

bool is_8bit_srgb(const std::filesystem::path& path) {
    const std::string ext = lowercase_extension(path);
    return ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".tga";
}

void write_image(const Image& image, const std::filesystem::path& path) {
    const Format format = format_of(path, "write");
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
        throw InputError("cannot write '" + path.string() + "': image " + std::to_string(image.width) + "x" +
                         std::to_string(image.height) + " holds " + std::to_string(image.pixels.size()) + " pixels");
    write_atomically(path, [&](const std::filesystem::path& temp) {
        switch (format) {
            case Format::Png: formats::write_png(image, temp); break;
            case Format::Pfm: formats::write_pfm(image, temp); break;
            case Format::Exr: formats::write_exr(image, temp); break;
            case Format::Hdr:
            case Format::Jpeg:
            case Format::Tga: break;  // format_of refuses to write these
        }
    });
}

Image read_image(const std::filesystem::path& path) {
    switch (format_of(path, "read")) {
        case Format::Png: return formats::read_png(path);
        case Format::Pfm: return formats::read_pfm(path);
        case Format::Exr: return formats::read_exr(path);
        case Format::Hdr: return formats::read_hdr(path);
        case Format::Jpeg: return formats::read_jpeg(path);
        case Format::Tga: return formats::read_tga(path);
    }
    throw InputError("cannot read '" + path.string() + "'");
}

namespace formats {

void write_bytes(const std::filesystem::path& path, const void* data, std::size_t size) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) throw InputError("cannot write '" + path.string() + "': " + reason_or(std::strerror(errno), "open failed"));
    const bool written = std::fwrite(data, 1, size, f) == size;
    const int saved = errno;
    const bool closed = std::fclose(f) == 0;
    if (!written || !closed)
        throw InputError("cannot write '" + path.string() + "': " +
                         reason_or(std::strerror(written ? errno : saved), "write failed"));
}

void check_image_size(const std::filesystem::path& path, const char* format, long long w, long long h) {
    if (w >= 1 && h >= 1 && w <= kMaxImageSide && h <= kMaxImageSide && w * h <= kMaxImagePixels) return;
    throw InputError("cannot read '" + path.string() + "': " + format + " size " + std::to_string(w) + "x" +
                     std::to_string(h) + " is out of range (each side 1.." + std::to_string(kMaxImageSide) +
                     ", at most " + std::to_string(kMaxImagePixels) + " pixels)");
}

void reserve_image(const std::filesystem::path& path, const char* format, long long w, long long h) {
    check_image_size(path, format, w, h);
    charge_load_memory(static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h) * sizeof(glm::vec3), path.string(),
                       std::string(format) + " image " + std::to_string(w) + "x" + std::to_string(h));
}

void check_image_file(const std::filesystem::path& path) {
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    std::string reason;
    if (!std::filesystem::exists(status)) reason = "no such file";
    else if (std::filesystem::is_directory(status)) reason = "is a directory";
    else if (!std::filesystem::is_regular_file(status)) reason = file_kind_problem(path);  // a FIFO, a device
    else if (std::filesystem::file_size(path, ec) > kMaxImageFileBytes)
        reason = "larger than the " + std::to_string(kMaxImageFileBytes >> 20) + " MiB an image may be";
    if (!reason.empty()) throw InputError("cannot read '" + path.string() + "': " + reason);
}

std::vector<unsigned char> read_bytes(const std::filesystem::path& path) {
    check_image_file(path);
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError("cannot read '" + path.string() + "': " + reason_or(std::strerror(errno), "open failed"));
    std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw InputError("cannot read '" + path.string() + "': read error");
    return bytes;
}

}  // namespace formats
}  // namespace sweeptrace
