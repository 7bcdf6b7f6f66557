#include "raytracer/scene/text_file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

#include "raytracer/input_error.hpp"
#include "raytracer/scene/read_files.hpp"

namespace sweeptrace {

std::string mib_text(std::uintmax_t bytes) {
    return std::to_string((bytes + (std::uintmax_t{1} << 20) - 1) >> 20) + " MiB";
}

void check_input_file(const std::filesystem::path& file, const char* what, std::uintmax_t max_bytes) {
    std::error_code ec;
    const auto status = std::filesystem::status(file, ec);
    std::string reason;
    if (!std::filesystem::exists(status))
        reason = "no such file";
    else if (std::filesystem::is_directory(status))
        reason = "it is a directory";
    else if (!std::filesystem::is_regular_file(status))
        reason = file_kind_problem(file);  // "is a FIFO, not a regular file", "is a device, ..."
    else if (const std::uintmax_t size = std::filesystem::file_size(file, ec); ec)
        reason = reason_or(ec.message().c_str(), "cannot get its size");
    else if (size > max_bytes)
        reason = "it is " + mib_text(size) + ", over the limit of " + mib_text(max_bytes) + " for a " + what;
    if (!reason.empty()) throw InputError(file.string() + ": cannot read " + what + ": " + reason);
}

std::string read_text_file(const std::filesystem::path& file, const char* what, std::uintmax_t max_bytes) {
    note_read_file(file);
    check_input_file(file, what, max_bytes);
    errno = 0;
    std::ifstream in(file, std::ios::binary);
    if (in) {
        std::ostringstream text;
        text << in.rdbuf();
        if (!in.bad()) return std::move(text).str();
    }
    throw InputError(file.string() + ": cannot read " + what + ": " + reason_or(std::strerror(errno), "read error"));
}

std::vector<std::string_view> words(std::string_view line) {
    const auto blank = [](char c) { return c == ' ' || c == '\t'; };
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && blank(line[i])) ++i;
        const std::size_t start = i;
        while (i < line.size() && !blank(line[i])) ++i;
        if (i > start) out.push_back(line.substr(start, i - start));
    }
    return out;
}

}  // namespace sweeptrace
