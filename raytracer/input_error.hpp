#pragma once
// Bad input from the user (scene, mesh, image, command line). The CLI prints what() on one line
// and exits with code 2; nothing is written. Messages name the file and where in it
// (JSON path such as `objects[3].radius`, or line and column).
//
// Whatever a message quotes (a key, a value, a file name, a library's reason), what() is one line
// of at most kMaxMessage bytes: control characters become '?', and an over-long message keeps its
// start (the file and place) and its end (the reason), with "..." between. A hostile file cannot
// turn the message into 200 KB of key path or a second line.
#include <cstddef>
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

// A library's reason for a failure, or `fallback` when it gave none (null, empty, or errno 0's
// "Success"): a message never ends in an empty reason.
inline std::string reason_or(const char* reason, const char* fallback) {
    const std::string_view r = reason ? std::string_view(reason) : std::string_view();
    if (r.empty() || r == "Success") return fallback;
    return std::string(r);
}

class InputError : public std::runtime_error {
public:
    static constexpr std::size_t kMaxMessage = 400;
    explicit InputError(const std::string& message) : std::runtime_error(one_line(message)) {}

private:
    static std::string one_line(const std::string& message) {
        std::string s = excerpt(message, kMaxMessage);
        for (char& c : s)
            if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
        return s;
    }
};

}  // namespace sweeptrace
