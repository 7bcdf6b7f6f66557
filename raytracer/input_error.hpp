#pragma once
// Bad input from the user (scene, mesh, image, command line). The CLI prints what() on one line
// and exits with code 2; nothing is written. Messages name the file and where in it
// (JSON path such as `objects[3].radius`, or line and column).
//
// Whatever a message quotes (a key, a value, a file name, a library's reason), what() is one line
// of at most kMaxMessage bytes: control characters are escaped (escape_control), and an over-long
// message keeps its start (the file and place) and its end (the reason), with "..." between. A
// hostile file cannot turn the message into 200 KB of key path, a second line that forges
// "sweeptrace: error:", or an ESC sequence that recolours the terminal.
#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace sweeptrace {

// Text quoted from input, at most `max` bytes: longer text keeps its head and tail around "...".
// The cuts fall between UTF-8 characters, so valid UTF-8 stays valid.
inline std::string excerpt(std::string_view s, std::size_t max = 60) {
    if (s.size() <= max) return std::string(s);
    auto continuation = [&](std::size_t i) { return i < s.size() && (static_cast<unsigned char>(s[i]) & 0xC0) == 0x80; };
    const std::size_t tail = max < 8 ? 0 : (max - 3) / 3;
    std::size_t head_end = max < 8 ? max : max - 3 - tail, tail_start = s.size() - tail;
    while (head_end > 0 && continuation(head_end)) --head_end;
    while (continuation(tail_start)) ++tail_start;
    if (max < 8) return std::string(s.substr(0, head_end));
    return std::string(s.substr(0, head_end)) + "..." + std::string(s.substr(tail_start));
}

// `s` with every control character (below 0x20, and DEL) written as an escape a reader can see:
// \n, \r, \t, and \xHH for the others (ESC is \x1b). For everything echoed from a file, in
// errors and warnings alike.
inline std::string escape_control(std::string_view s) {
    std::string out;
    out.reserve(s.size());
    for (const char ch : s) {
        const auto c = static_cast<unsigned char>(ch);
        if (c >= 0x20 && c != 0x7f) out += ch;
        else if (c == '\n') out += "\\n";
        else if (c == '\r') out += "\\r";
        else if (c == '\t') out += "\\t";
        else {
            constexpr char kHex[] = "0123456789abcdef";
            out += "\\x";
            out += kHex[c >> 4];
            out += kHex[c & 15];
        }
    }
    return out;
}

// A library's reason for a failure, or `fallback` when it gave none (null, empty, or errno 0's
// "Success"): a message never ends in an empty reason.
inline std::string reason_or(const char* reason, const char* fallback) {
    const std::string_view r = reason ? std::string_view(reason) : std::string_view();
    if (r.empty() || r == "Success") return fallback;
    return std::string(r);
}

// Why `file` cannot be read as a file, for a message after its name: "not found", "is a
// directory", "is a FIFO", "is a device" (a FIFO or /dev/zero would block or never end), "is a
// socket"; empty for a regular file (symlinks followed).
inline std::string file_kind_problem(const std::filesystem::path& file) {
    std::error_code ec;
    switch (std::filesystem::status(file, ec).type()) {
        case std::filesystem::file_type::regular: return {};
        case std::filesystem::file_type::directory: return "is a directory, not a file";
        case std::filesystem::file_type::fifo: return "is a FIFO, not a regular file";
        case std::filesystem::file_type::block:
        case std::filesystem::file_type::character: return "is a device, not a regular file";
        case std::filesystem::file_type::socket: return "is a socket, not a regular file";
        case std::filesystem::file_type::not_found:
        case std::filesystem::file_type::none: return "not found";
        default: return "is not a regular file";
    }
}

class InputError : public std::runtime_error {
public:
    static constexpr std::size_t kMaxMessage = 400;
    explicit InputError(const std::string& message) : std::runtime_error(one_line(message)) {}

private:
    static std::string one_line(const std::string& message) { return excerpt(escape_control(message), kMaxMessage); }
};

}  // namespace sweeptrace
