#pragma once
// pbrt-v4 scene text -> tokens. The grammar's lexical level (pbrt.org/fileformat-v4): `#` starts a
// comment to the end of the line; "quoted strings" (with \" \\ \n \t escapes) never span a line;
// `[` and `]` are tokens of their own; everything else is a bare word split at white space
// (directive names, numbers, bare true/false). Bounded: a token longer than kMaxTokenBytes or a
// file of more than kMaxTokens tokens is refused (the file size is bounded before, text_file.hpp).
#include <cstddef>
#include <string>
#include <vector>

#include "raytracer/scene/pbrt/pbrt_diagnostics.hpp"

namespace sweeptrace::pbrt {

inline constexpr std::size_t kMaxTokenBytes = 4096;
inline constexpr std::size_t kMaxTokens = std::size_t{1} << 23;  // ~8M: a 16 MiB file of "1 " pairs

struct Token {
    enum class Kind { Word, String, Open, Close } kind = Kind::Word;
    std::string text;  // a String's text without quotes, escapes resolved
    int line = 0;
};

// Fails (Diagnostics::fail, naming file:line) on an unterminated string, a control byte, an
// over-long token or too many tokens.
std::vector<Token> tokenize(const std::string& text, const Where& file, const Diagnostics& diag);

}  // namespace sweeptrace::pbrt
