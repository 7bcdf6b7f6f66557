#pragma once
#include <filesystem>
#include <string>

namespace sweeptrace {

// The whole file as bytes. Throws InputError "<file>: cannot read <what>: <reason>" when it is
// missing, a directory, or unreadable.
std::string read_text_file(const std::filesystem::path& file, const char* what);

}  // namespace sweeptrace
