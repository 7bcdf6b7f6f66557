#include "raytracer/scene/gzip_file.hpp"

#include <zlib.h>

#include <algorithm>
#include <limits>
#include <new>

#include "raytracer/image/image.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/scene/text_file.hpp"

namespace sweeptrace {

namespace {

// zlib counts in uInt (32 bits): larger spans are handed over in pieces of at most this.
constexpr std::size_t kMaxStep = std::numeric_limits<uInt>::max();

// A z_stream set up for gzip members only (16 + MAX_WBITS: no raw deflate, no zlib wrapper), ended
// on every way out.
class Inflater {
public:
    Inflater() {
        const int r = inflateInit2(&s, 16 + MAX_WBITS);
        if (r == Z_MEM_ERROR) throw std::bad_alloc();
        if (r != Z_OK) throw std::logic_error("inflateInit2 failed: " + reason_or(s.msg, "unknown zlib error"));
    }
    ~Inflater() { inflateEnd(&s); }
    Inflater(const Inflater&) = delete;
    Inflater& operator=(const Inflater&) = delete;
    z_stream s{};
};

}  // namespace

bool is_gzip_name(const std::filesystem::path& file) { return lowercase_extension(file) == ".gz"; }

std::string content_extension(const std::filesystem::path& file) {
    return lowercase_extension(is_gzip_name(file) ? file.stem() : file);
}

std::string gunzip(std::string_view compressed, const std::string& name, const char* what, std::uintmax_t max_bytes,
                   TransientLoadCharge* charge) {
    if (compressed.empty()) throw InputError(name + ": not a valid gzip file (empty file)");
    // One byte past the limit proves the output is over it; the buffer never grows beyond.
    const std::uintmax_t cap = max_bytes + 1;
    Inflater z;
    std::size_t fed = 0, used = 0;
    // The buffer charged before each allocation, by what it grows.
    const auto grow_charge = [&](std::size_t from, std::size_t to) {
        if (charge) charge->add(to - from, name, std::string("the inflated ") + what + " (growing to " + byte_text(to) + ")");
    };
    // Text and meshes compress 3-10x; the guess only saves a few doublings.
    const auto first = static_cast<std::size_t>(std::min<std::uintmax_t>(cap, std::max<std::uintmax_t>(1 << 16, 4 * compressed.size())));
    grow_charge(0, first);
    std::string out(first, '\0');
    const auto over_limit = [&] {
        return InputError(name + ": decompressed size exceeds the " + mib_text(max_bytes) + " limit for a " + what);
    };
    for (;;) {
        if (used == out.size()) {
            if (out.size() >= cap) throw over_limit();
            const auto next = static_cast<std::size_t>(std::min<std::uintmax_t>(cap, 2 * std::uintmax_t{out.size()}));
            grow_charge(out.size(), next);
            out.resize(next);
        }
        if (z.s.avail_in == 0 && fed < compressed.size()) {
            const std::size_t step = std::min(kMaxStep, compressed.size() - fed);
            z.s.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data() + fed));
            z.s.avail_in = static_cast<uInt>(step);
            fed += step;
        }
        z.s.next_out = reinterpret_cast<Bytef*>(out.data() + used);
        z.s.avail_out = static_cast<uInt>(std::min(kMaxStep, out.size() - used));
        const int r = inflate(&z.s, Z_NO_FLUSH);
        used = static_cast<std::size_t>(reinterpret_cast<char*>(z.s.next_out) - out.data());
        const bool input_left = z.s.avail_in > 0 || fed < compressed.size();
        if (r == Z_STREAM_END) {
            if (!input_left) break;
            inflateReset(&z.s);  // another member follows (it must be gzip too, or inflate says why not)
        } else if (r == Z_BUF_ERROR) {
            // No progress possible: with room to write, only more input would help, and there is
            // none. (Without room, the buffer grows on the next turn.)
            if (z.s.avail_out > 0 && !input_left) throw InputError(name + ": truncated gzip data");
        } else if (r == Z_MEM_ERROR) {
            throw std::bad_alloc();
        } else if (r != Z_OK) {
            throw InputError(name + ": not a valid gzip file (" + reason_or(z.s.msg, "corrupt data") + ")");
        }
    }
    if (used > max_bytes) throw over_limit();  // the last member ended exactly one byte over
    out.resize(used);
    return out;
}

FileBytes read_maybe_gzipped(const std::filesystem::path& file, const char* what, std::uintmax_t max_bytes) {
    FileBytes f;
    f.bytes = read_text_file(file, what, max_bytes);
    if (is_gzip_name(file)) f.bytes = gunzip(f.bytes, file.string(), what, max_bytes, &f.charge);
    return f;
}

}  // namespace sweeptrace
