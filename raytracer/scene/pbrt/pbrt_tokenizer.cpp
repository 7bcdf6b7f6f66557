#include "raytracer/scene/pbrt/pbrt_tokenizer.hpp"

#include "raytracer/input_error.hpp"

namespace sweeptrace::pbrt {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

}  // namespace

std::vector<Token> tokenize(const std::string& text, const Where& file, const Diagnostics& diag) {
    std::vector<Token> tokens;
    Where at = file;
    at.line = 1;
    auto push = [&](Token t) {
        if (tokens.size() >= kMaxTokens)
            diag.fail(at, "more than " + std::to_string(kMaxTokens) + " tokens in one file; split it with Include");
        tokens.push_back(std::move(t));
    };
    const std::size_t n = text.size();
    std::size_t i = 0;
    while (i < n) {
        const char c = text[i];
        if (c == '\n') {
            ++at.line;
            ++i;
        } else if (is_space(c)) {
            ++i;
        } else if (c == '#') {
            while (i < n && text[i] != '\n') ++i;
        } else if (c == '[' || c == ']') {
            push({c == '[' ? Token::Kind::Open : Token::Kind::Close, std::string(1, c), at.line});
            ++i;
        } else if (c == '"') {
            Token t{Token::Kind::String, {}, at.line};
            ++i;
            for (;;) {
                if (i >= n || text[i] == '\n') diag.fail(at, "unterminated string: close it with '\"' on the same line");
                char d = text[i++];
                if (d == '"') break;
                if (d == '\\') {
                    if (i >= n) diag.fail(at, "unterminated string: close it with '\"' on the same line");
                    const char e = text[i++];
                    d = e == 'n' ? '\n' : e == 't' ? '\t' : e;
                }
                if (t.text.size() >= kMaxTokenBytes)
                    diag.fail(at, "a string longer than " + std::to_string(kMaxTokenBytes) + " bytes");
                t.text.push_back(d);
            }
            push(std::move(t));
        } else {
            Token t{Token::Kind::Word, {}, at.line};
            while (i < n && !is_space(text[i]) && text[i] != '"' && text[i] != '[' && text[i] != ']' && text[i] != '#') {
                const auto u = static_cast<unsigned char>(text[i]);
                if (u < 0x20 || u == 0x7f)
                    diag.fail(at, "control byte " + std::to_string(u) + " in the text (a binary file? pbrt scenes are text)");
                if (t.text.size() >= kMaxTokenBytes)
                    diag.fail(at, "a word longer than " + std::to_string(kMaxTokenBytes) + " bytes");
                t.text.push_back(text[i++]);
            }
            push(std::move(t));
        }
    }
    return tokens;
}

}  // namespace sweeptrace::pbrt
