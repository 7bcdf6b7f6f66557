#pragma once
// gzip-compressed input (a name ending in .gz, any case), as pbrt-v4 reads its scenes'
// `mesh.ply.gz` meshes and `hair.pbrt.gz` Includes: the file inflated in memory by zlib, bounded by
// the limit the uncompressed file would have (text_file.hpp: kMaxMeshFileBytes, kMaxSceneFileBytes).
// A small file that inflates to gigabytes (a gzip bomb) is refused as soon as its output passes the
// limit: inflation stops there and the buffer never holds more than limit + 1 bytes. Concatenated
// members (`cat a.gz b.gz`, multi-member gzip) are read one after another, as gunzip reads them;
// anything after the last member that is not another member is an error.
//
// Errors are InputError, one line naming the file:
//   "<file>: decompressed size exceeds the N MiB limit for a <what>"
//   "<file>: not a valid gzip file (<zlib's reason>)"   (also an empty file)
//   "<file>: truncated gzip data"                       (the data ends inside a member)
// and check_input_file's for the compressed file itself (missing, not a regular file, over the
// limit already compressed).
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace sweeptrace {

// True when the file's name ends in .gz (any case).
bool is_gzip_name(const std::filesystem::path& file);

// The extension of what the file holds, in lower case, looking through a final .gz: ".ply" for
// mesh.PLY.gz and for mesh.ply, ".pbrt" for hair.pbrt.gz.
std::string content_extension(const std::filesystem::path& file);

// `compressed` (the bytes of `name`, for messages) inflated, at most `max_bytes` of output.
std::string gunzip(std::string_view compressed, const std::string& name, const char* what, std::uintmax_t max_bytes);

// The whole file as bytes: inflated (gunzip) when is_gzip_name, otherwise read_text_file's bytes.
// `max_bytes` bounds the compressed file and its decompressed bytes alike.
std::string read_maybe_gzipped(const std::filesystem::path& file, const char* what, std::uintmax_t max_bytes);

}  // namespace sweeptrace
