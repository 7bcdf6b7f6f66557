#pragma once
// The files a scene load reads, one list filled by the readers themselves as they open a file
// (read_text_file: scene JSON, .mtl, .pbrt and its Includes, .spd spectra, gzip files; the OBJ
// and PLY loaders through it; read_image_path: textures, environment, normal and bump maps), so
// that no reader can be forgotten by a list kept by hand. The command line refuses an output
// that is one of them (cli/output_guard.hpp): `-o albedo.png` would replace the scene's texture.
//
// A ReadFilesScope collects the files noted while it lives (scopes nest: an inner one's files
// are the outer one's too). Loading is single-threaded; the scopes are per thread.
#include <filesystem>
#include <vector>

namespace sweeptrace {

class ReadFilesScope {
public:
    ReadFilesScope();
    ~ReadFilesScope();
    ReadFilesScope(const ReadFilesScope&) = delete;
    ReadFilesScope& operator=(const ReadFilesScope&) = delete;
    // Each file once, as it was opened (relative to the working directory, or absolute).
    const std::vector<std::filesystem::path>& files() const { return files_; }

private:
    std::vector<std::filesystem::path> files_;
};

// Adds `file` to every open scope (nothing without one).
void note_read_file(const std::filesystem::path& file);

}  // namespace sweeptrace
