#pragma once
// gzip-compressed input (a name ending in .gz, any case), as pbrt-v4 reads its scenes'
// `mesh.ply.gz` meshes and `hair.pbrt.gz` Includes: the file inflated in memory by zlib, bounded by
// the limit the uncompressed file would have (text_file.hpp: kMaxMeshFileBytes, kMaxSceneFileBytes).
// A small file that inflates to gigabytes (a gzip bomb) is refused as soon as its output passes the
// limit: inflation stops there and the buffer never holds more than limit + 1 bytes. Concatenated
// members (`cat a.gz b.gz`, multi-member gzip) are read one after another, as gunzip reads them;
// anything after the last member that is not another member is an error. The inflated buffer is
// charged to the load budget (load_budget.hpp) before each time it grows, and given back when the
// caller has parsed it (FileBytes): a 2 MB .ply.gz may inflate to the 512 MiB mesh limit, which
// the budget must see beside the mesh being built from it.
//
// Errors are InputError, one line naming the file:
//   "<file>: decompressed size exceeds the N MiB limit for a <what>"
//   "<file>: not a valid gzip file (<zlib's reason>)"   (also an empty file)
//   "<file>: truncated gzip data"                       (the data ends inside a member)
//   "<file>: the inflated <what> (growing to N) needs ..., over the load budget of ..."
// and check_input_file's for the compressed file itself (missing, not a regular file, over the
// limit already compressed).
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "raytracer/load_budget.hpp"

namespace sweeptrace {

// A file's bytes as read (inflated when gzip) and their charge to the load budget, given back
// when this is destroyed: keep it while the bytes are parsed.
struct FileBytes {
    std::string bytes;
    TransientLoadCharge charge;
};

// True when the file's name ends in .gz (any case).
bool is_gzip_name(const std::filesystem::path& file);

// The extension of what the file holds, in lower case, looking through a final .gz: ".ply" for
// mesh.PLY.gz and for mesh.ply, ".pbrt" for hair.pbrt.gz.
std::string content_extension(const std::filesystem::path& file);

// `compressed` (the bytes of `name`, for messages) inflated, at most `max_bytes` of output; with
// `charge`, the output buffer charged to the load budget before it is allocated and each time
// before it grows.
std::string gunzip(std::string_view compressed, const std::string& name, const char* what, std::uintmax_t max_bytes,
                   TransientLoadCharge* charge = nullptr);

// The whole file as bytes: inflated (gunzip, charged) when is_gzip_name, otherwise
// read_text_file's bytes (bounded by the file's size on disk, not charged). `max_bytes` bounds
// the compressed file and its decompressed bytes alike.
FileBytes read_maybe_gzipped(const std::filesystem::path& file, const char* what, std::uintmax_t max_bytes);

}  // namespace sweeptrace
