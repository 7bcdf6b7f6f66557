// Radiance .hdr (RGBE), read only (the renderer writes .pfm and .exr for linear output).
// Decoded here, not by stb_image: Debian's stb loops forever on an RLE count of 0 at the end of
// the data and fills missing pixels with zeros (both found by tests/fuzz's hdr harness), and
// the format is small: header lines, a resolution line, then scanlines, each either flat RGBE
// or new-style run-length encoded per channel. Every count and length is checked against the
// bytes left and the pixels left, so a file decodes to exactly the image it describes or fails.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "raytracer/image/image_formats.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace::formats {
namespace {

class Reader {
public:
    Reader(const std::vector<unsigned char>& bytes, const std::filesystem::path& path) : bytes_(bytes), path_(path) {}

    [[noreturn]] void fail(const std::string& what) const {
        throw InputError("cannot read '" + path_.string() + "': not a valid HDR file (" + what + ")");
    }
    std::size_t left() const { return bytes_.size() - at_; }
    std::size_t at() const { return at_; }
    unsigned char byte() {
        if (at_ >= bytes_.size()) fail("data ends at byte " + std::to_string(at_));
        return bytes_[at_++];
    }
    // A header line without its '\n'; header lines are short, so a long one is an error.
    std::string line() {
        std::string s;
        while (true) {
            if (at_ >= bytes_.size()) fail("header ends without a resolution line");
            const char c = static_cast<char>(bytes_[at_++]);
            if (c == '\n') return s;
            if (s.size() >= 256) fail("header line at byte " + std::to_string(at_ - s.size() - 1) + " is too long");
            s += c;
        }
    }

private:
    const std::vector<unsigned char>& bytes_;
    const std::filesystem::path& path_;
    std::size_t at_ = 0;
};

// The header up to and including the resolution line; returns width and height. Only the
// standard orientation (-Y H +X W: top row first, left to right) is read, as by every tool
// that writes .hdr for environment maps.
void read_header(Reader& in, const std::vector<unsigned char>& bytes, const std::filesystem::path& path, int& w,
                 int& h) {
    // The magic line is compared before anything is read as a line: a binary file of another
    // format has no newline to end its "first line".
    const auto starts = [&](const std::string& magic) {
        return bytes.size() >= magic.size() && std::equal(magic.begin(), magic.end(), bytes.begin());
    };
    if (!starts("#?RADIANCE\n") && !starts("#?RGBE\n"))
        throw InputError("cannot read '" + path.string() + "': not a Radiance HDR file (no '#?RADIANCE' first line)");
    in.line();
    bool rgbe = false;
    for (std::string l = in.line(); !l.empty(); l = in.line()) {
        if (l.rfind("FORMAT=", 0) == 0) {
            if (l != "FORMAT=32-bit_rle_rgbe") in.fail("format '" + l.substr(7) + "' (only 32-bit_rle_rgbe is read)");
            rgbe = true;
        }
    }
    if (!rgbe) in.fail("no FORMAT=32-bit_rle_rgbe line");
    const std::string res = in.line();
    long long hh = 0, ww = 0;
    char tail = 0;
    if (std::sscanf(res.c_str(), "-Y %lld +X %lld%c", &hh, &ww, &tail) != 2)
        in.fail("the resolution line is not '-Y height +X width'");
    reserve_image(path, "HDR", ww, hh);
    w = static_cast<int>(ww);
    h = static_cast<int>(hh);
}

// One scanline's RGBE bytes into `line` (4 per pixel): new-style RLE when it starts with
// 2, 2 and the width (widths 8..32767 only), flat otherwise.
void read_scanline(Reader& in, int w, int y, std::vector<unsigned char>& line) {
    const bool rle_width = w >= 8 && w < 32768;
    if (rle_width && in.left() >= 4) {
        const unsigned char b0 = in.byte(), b1 = in.byte(), b2 = in.byte(), b3 = in.byte();
        if (b0 == 2 && b1 == 2 && (b2 & 0x80) == 0) {
            if (((b2 << 8) | b3) != w) in.fail("scanline " + std::to_string(y) + " says width " + std::to_string((b2 << 8) | b3));
            for (int c = 0; c < 4; ++c)
                for (int x = 0; x < w;) {
                    int count = in.byte();
                    const bool run = count > 128;
                    if (run) count -= 128;
                    if (count == 0 || count > w - x)
                        in.fail("scanline " + std::to_string(y) + ": run of " + std::to_string(count) + " at pixel " +
                                std::to_string(x) + " of " + std::to_string(w));
                    const unsigned char value = run ? in.byte() : 0;
                    for (int k = 0; k < count; ++k, ++x) line[4 * x + c] = run ? value : in.byte();
                }
            return;
        }
        line[0] = b0, line[1] = b1, line[2] = b2, line[3] = b3;  // a flat scanline's first pixel
        for (std::size_t i = 4; i < line.size(); ++i) line[i] = in.byte();
        return;
    }
    for (unsigned char& b : line) b = in.byte();
}

}  // namespace

Image read_hdr(const std::filesystem::path& path) {
    const std::vector<unsigned char> bytes = read_bytes(path);
    Reader in(bytes, path);
    int w = 0, h = 0;
    read_header(in, bytes, path, w, h);
    // Each scanline takes at least 4 + 8 ceil(w / 127) bytes (RLE: a header and per channel runs
    // of at most 127 in 2 bytes; narrower than 8, 4 per pixel): checked before w x h floats are
    // allocated, so a 100-byte file cannot claim 8000 x 8000 pixels.
    const long long per_line = w < 8 ? 4LL * w : 4 + 8 * ((w + 126LL) / 127);
    if (static_cast<long long>(in.left()) < per_line * h)
        in.fail(std::to_string(w) + "x" + std::to_string(h) + " pixels need at least " + std::to_string(per_line * h) +
                " bytes of data, the file has " + std::to_string(in.left()));
    Image image(w, h);
    std::vector<unsigned char> line(static_cast<std::size_t>(w) * 4);
    for (int y = 0; y < h; ++y) {
        read_scanline(in, w, y, line);
        for (int x = 0; x < w; ++x) {
            const unsigned char* p = &line[4 * static_cast<std::size_t>(x)];
            // Mantissa bytes times 2^(exponent - 136), as stb and most readers decode (Radiance's
            // own adds half a step to the mantissa); exponent 0 is black.
            const float f = p[3] == 0 ? 0.0f : std::ldexp(1.0f, static_cast<int>(p[3]) - 136);
            image.at(x, y) = glm::vec3(p[0] * f, p[1] * f, p[2] * f);
        }
    }
    return image;
}

}  // namespace sweeptrace::formats
