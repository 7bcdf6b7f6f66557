#include "raytracer/cli/report_text.hpp"

#include <fstream>

#include "raytracer/image/atomic_file.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace {

std::string markup_escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            default: out += c;
        }
    }
    return out;
}

void write_text_file(const std::filesystem::path& path, const std::string& text) {
    write_atomically(path, [&](const std::filesystem::path& temp) {
        std::ofstream out(temp, std::ios::binary);
        out << text;
        out.close();
        if (!out) throw InputError("cannot write '" + path.string() + "'");
    });
}

}  // namespace sweeptrace
