#pragma once
// One reader and one writer per file format; image_io.cpp picks by extension and makes the write
// atomic. Writers write to exactly the path given (the temporary file); readers throw InputError
// naming the file.
#include <cstddef>
#include <filesystem>
#include <vector>

#include "raytracer/image/image.hpp"

namespace sweeptrace::formats {

void write_png(const Image& image, const std::filesystem::path& path);
Image read_png(const std::filesystem::path& path);

void write_pfm(const Image& image, const std::filesystem::path& path);
Image read_pfm(const std::filesystem::path& path);

void write_exr(const Image& image, const std::filesystem::path& path);
Image read_exr(const std::filesystem::path& path);

// Radiance .hdr (RGBE), read only: linear float.
Image read_hdr(const std::filesystem::path& path);

}  // namespace sweeptrace::formats

namespace sweeptrace::formats {

// Writes `size` bytes to `path` (truncating); throws InputError naming `path` on any failure.
void write_bytes(const std::filesystem::path& path, const void* data, std::size_t size);

// Whole file into memory; throws InputError naming `path` when it cannot be opened or read.
std::vector<unsigned char> read_bytes(const std::filesystem::path& path);

}  // namespace sweeptrace::formats
