#pragma once
// One reader and one writer per file format; image_io.cpp picks by extension and makes the write
// atomic. Writers write to exactly the path given (the temporary file); readers throw InputError
// naming the file.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <utility>
#include <vector>

#include "raytracer/image/image.hpp"

namespace sweeptrace::formats {

void write_png(const Image& image, const std::filesystem::path& path);
Image read_png(const std::filesystem::path& path);

void write_pfm(const Image& image, const std::filesystem::path& path);
Image read_pfm(const std::filesystem::path& path);

void write_exr(const Image& image, const std::filesystem::path& path);
Image read_exr(const std::filesystem::path& path);
// The data window's width and height as the file's first header states it, read from the bytes
// before OpenEXR opens the file (which allocates from it); nullopt when the bytes are not a
// plain EXR header (OpenEXR then says what is wrong). Both EXR readers check it first.
std::optional<std::pair<long long, long long>> exr_header_window(const std::filesystem::path& path);

// Radiance .hdr (RGBE), read only: linear float.
Image read_hdr(const std::filesystem::path& path);

// JPEG (.jpg, .jpeg), read only: 8-bit sRGB decoded to linear, like a PNG.
Image read_jpeg(const std::filesystem::path& path);

// Truevision TGA (.tga), read only: 8-bit sRGB decoded to linear, like a PNG; alpha dropped.
Image read_tga(const std::filesystem::path& path);

}  // namespace sweeptrace::formats

namespace sweeptrace::formats {

// What the readers accept, checked on the file's size and the header's dimensions before the
// pixels are decoded or allocated: a 1 KB EXR or PNG header may claim 65536 x 65536 pixels
// (51 GB as floats). 2^26 pixels (8192 x 8192, 805 MB as an Image) is far above any render the
// tests or docs compare.
inline constexpr std::uintmax_t kMaxImageFileBytes = std::uintmax_t{1} << 30;  // 1 GiB
inline constexpr long long kMaxImageSide = 1 << 16;
inline constexpr long long kMaxImagePixels = 1LL << 26;

// Throws InputError "cannot read '<path>': <format> size WxH is out of range ..." unless
// 1 <= w, h <= kMaxImageSide and w * h <= kMaxImagePixels.
void check_image_size(const std::filesystem::path& path, const char* format, long long w, long long h);

// check_image_size, then the decoded image (w x h linear RGB floats) charged to the scene load's
// memory budget (load_budget.hpp), before the reader allocates it: the readers' one entry.
void reserve_image(const std::filesystem::path& path, const char* format, long long w, long long h);

// Throws InputError naming `path` unless it is a regular file of at most kMaxImageFileBytes.
void check_image_file(const std::filesystem::path& path);

// Writes `size` bytes to `path` (truncating); throws InputError naming `path` on any failure.
void write_bytes(const std::filesystem::path& path, const void* data, std::size_t size);

// Whole file into memory; throws InputError naming `path` when it cannot be opened or read.
std::vector<unsigned char> read_bytes(const std::filesystem::path& path);

}  // namespace sweeptrace::formats
