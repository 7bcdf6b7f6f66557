#include "raytracer/scene/text_file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

#include "raytracer/input_error.hpp"

namespace sweeptrace {

std::string read_text_file(const std::filesystem::path& file, const char* what) {
    std::error_code ec;
    const auto status = std::filesystem::status(file, ec);
    std::string reason;
    if (!std::filesystem::exists(status))
        reason = "no such file";
    else if (std::filesystem::is_directory(status))
        reason = "it is a directory";
    if (reason.empty()) {
        std::ifstream in(file, std::ios::binary);
        if (in) {
            std::ostringstream text;
            text << in.rdbuf();
            if (!in.bad()) return std::move(text).str();
        }
        reason = std::strerror(errno);
    }
    throw InputError(file.string() + ": cannot read " + what + ": " + reason);
}

}  // namespace sweeptrace
