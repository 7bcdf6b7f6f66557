#include "raytracer/scene/read_files.hpp"

#include <algorithm>

namespace sweeptrace {

namespace {

thread_local std::vector<std::vector<std::filesystem::path>*> open_scopes;

}  // namespace

ReadFilesScope::ReadFilesScope() { open_scopes.push_back(&files_); }

ReadFilesScope::~ReadFilesScope() { std::erase(open_scopes, &files_); }

void note_read_file(const std::filesystem::path& file) {
    const std::filesystem::path normal = file.lexically_normal();
    for (std::vector<std::filesystem::path>* files : open_scopes)
        if (std::find(files->begin(), files->end(), normal) == files->end()) files->push_back(normal);
}

}  // namespace sweeptrace
