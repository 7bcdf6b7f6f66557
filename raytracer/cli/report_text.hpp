#pragma once
// Text helpers shared by the diff reports (JSON, JUnit XML, HTML).
#include <filesystem>
#include <string>

namespace sweeptrace {

// & < > " ' escaped for XML and HTML text and attribute values.
std::string markup_escape(const std::string& text);

// The whole file written atomically (write_atomically); InputError naming `path` on failure.
void write_text_file(const std::filesystem::path& path, const std::string& text);

}  // namespace sweeptrace
