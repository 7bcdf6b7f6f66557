#include "raytracer/scene/ply_loader.hpp"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "raytracer/input_error.hpp"
#include "raytracer/load_budget.hpp"
#include "raytracer/scene/gzip_file.hpp"
#include "raytracer/scene/text_file.hpp"

namespace sweeptrace {

namespace {

enum class Format { Ascii, BinaryLittle, BinaryBig };
enum class Scalar { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

// The header's bounds: real files have 2-3 elements of a dozen properties; these keep a hostile
// header from costing more than a few KB of bookkeeping.
constexpr std::size_t kMaxElements = 64, kMaxProperties = 64, kMaxCorners = 255;

struct Property {
    std::string name;
    Scalar type = Scalar::Float32;
    bool list = false;
    Scalar count_type = Scalar::UInt8;  // list only
};

struct Element {
    std::string name;
    std::uint64_t count = 0;
    std::vector<Property> properties;
    std::size_t line = 0;  // header line, for messages
};

std::optional<Scalar> scalar_named(std::string_view s) {
    if (s == "char" || s == "int8") return Scalar::Int8;
    if (s == "uchar" || s == "uint8") return Scalar::UInt8;
    if (s == "short" || s == "int16") return Scalar::Int16;
    if (s == "ushort" || s == "uint16") return Scalar::UInt16;
    if (s == "int" || s == "int32") return Scalar::Int32;
    if (s == "uint" || s == "uint32") return Scalar::UInt32;
    if (s == "float" || s == "float32") return Scalar::Float32;
    if (s == "double" || s == "float64") return Scalar::Float64;
    return std::nullopt;
}

std::size_t scalar_size(Scalar t) {
    switch (t) {
        case Scalar::Int8: case Scalar::UInt8: return 1;
        case Scalar::Int16: case Scalar::UInt16: return 2;
        case Scalar::Int32: case Scalar::UInt32: case Scalar::Float32: return 4;
        case Scalar::Float64: return 8;
    }
    return 8;
}

// A number as a message shows it: integers without a fraction.
std::string shown(double v) {
    if (std::floor(v) == v && std::abs(v) < 1e15) return std::to_string(static_cast<long long>(v));
    char buf[32];
    const auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return ec == std::errc() ? std::string(buf, p) : std::string("?");
}

bool is_integer(Scalar t) { return t != Scalar::Float32 && t != Scalar::Float64; }


struct Header {
    Format format = Format::Ascii;
    std::vector<Element> elements;
    std::size_t data_start = 0;  // byte offset of the first byte after end_header's newline
    std::size_t data_line = 0;   // the line number the data starts on (ASCII)
};

Header read_header(std::string_view bytes, const std::string& name) {
    Header h;
    std::size_t pos = 0, line_no = 0;
    bool have_format = false;
    auto fail = [&](const std::string& what) -> void {
        throw InputError(name + ": header line " + std::to_string(line_no) + ": " + what);
    };
    while (true) {
        if (pos >= bytes.size()) {
            ++line_no;
            fail("the file ends inside the header (no end_header line)");
        }
        const std::size_t end = bytes.find('\n', pos);
        if (end == std::string_view::npos) {
            ++line_no;
            fail("the file ends inside the header (no end_header line)");
        }
        std::string_view line = bytes.substr(pos, end - pos);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        pos = end + 1;
        ++line_no;
        if (line_no == 1) {
            if (line != "ply") fail("not a PLY file: it must start with a line \"ply\"");
            continue;
        }
        const std::vector<std::string_view> w = words(line);
        if (w.empty()) continue;
        if (w[0] == "comment" || w[0] == "obj_info") continue;
        if (w[0] == "end_header") break;
        if (w[0] == "format") {
            if (w.size() != 3 || w[2] != "1.0") fail("expected \"format <ascii|binary_little_endian|binary_big_endian> 1.0\"");
            if (w[1] == "ascii") h.format = Format::Ascii;
            else if (w[1] == "binary_little_endian") h.format = Format::BinaryLittle;
            else if (w[1] == "binary_big_endian") h.format = Format::BinaryBig;
            else fail("unknown format \"" + excerpt(w[1]) + "\" (known: ascii, binary_little_endian, binary_big_endian)");
            have_format = true;
        } else if (w[0] == "element") {
            if (w.size() != 3) fail("expected \"element <name> <count>\"");
            if (h.elements.size() >= kMaxElements) fail("more than " + std::to_string(kMaxElements) + " elements");
            Element e;
            e.name = std::string(w[1]);
            e.line = line_no;
            const auto [p, ec] = std::from_chars(w[2].data(), w[2].data() + w[2].size(), e.count);
            if (ec != std::errc() || p != w[2].data() + w[2].size())
                fail("element count \"" + excerpt(w[2]) + "\" is not a non-negative integer");
            h.elements.push_back(std::move(e));
        } else if (w[0] == "property") {
            if (h.elements.empty()) fail("a property before any element");
            Element& e = h.elements.back();
            if (e.properties.size() >= kMaxProperties) fail("more than " + std::to_string(kMaxProperties) + " properties");
            Property p;
            if (w.size() == 5 && w[1] == "list") {
                const auto count = scalar_named(w[2]), item = scalar_named(w[3]);
                if (!count || !item) fail("unknown type in \"" + excerpt(line) + "\" (known: char uchar short ushort int uint float double, or int8 ... float64)");
                if (!is_integer(*count)) fail("a list's count type must be an integer type");
                p = Property{std::string(w[4]), *item, true, *count};
            } else if (w.size() == 3) {
                const auto t = scalar_named(w[1]);
                if (!t) fail("unknown type \"" + excerpt(w[1]) + "\" (known: char uchar short ushort int uint float double, or int8 ... float64)");
                p = Property{std::string(w[2]), *t, false, Scalar::UInt8};
            } else {
                fail("expected \"property <type> <name>\" or \"property list <count type> <item type> <name>\"");
            }
            e.properties.push_back(std::move(p));
        } else {
            fail("unknown header keyword \"" + excerpt(w[0]) + "\"");
        }
    }
    if (!have_format) fail("end_header before any format line");
    h.data_start = pos;
    h.data_line = line_no + 1;
    return h;
}

// Reads the data section one number at a time, in either encoding, knowing where it is.
class DataReader {
public:
    DataReader(std::string_view bytes, const Header& h, const std::string& name)
        : bytes_(bytes), pos_(h.data_start), line_(h.data_line), format_(h.format), name_(name) {}

    // "byte N" or "line N": where the next number starts.
    [[noreturn]] void fail(const std::string& what) { throw InputError(name_ + ": " + where() + ": " + what); }
    std::string where() {
        return where_label(place());
    }

    // The number where() shows, for a place to be named later (where_label).
    std::uint64_t place() {
        if (format_ != Format::Ascii) return pos_;
        skip_space();
        return line_;
    }
    std::string where_label(std::uint64_t place) const {
        return (format_ == Format::Ascii ? "line " : "byte ") + std::to_string(place);
    }

    std::size_t remaining() const { return bytes_.size() - pos_; }
    bool ascii() const { return format_ == Format::Ascii; }

    double read(Scalar t) {
        if (format_ == Format::Ascii) return read_ascii(t);
        const std::size_t n = scalar_size(t);
        if (remaining() < n) fail("the data ends early (a record is cut short)");
        std::uint64_t v = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const auto b = static_cast<std::uint64_t>(static_cast<unsigned char>(bytes_[pos_ + i]));
            v |= format_ == Format::BinaryLittle ? b << (8 * i) : b << (8 * (n - 1 - i));
        }
        pos_ += n;
        switch (t) {
            case Scalar::Int8: return static_cast<std::int8_t>(v);
            case Scalar::UInt8: return static_cast<std::uint8_t>(v);
            case Scalar::Int16: return static_cast<std::int16_t>(v);
            case Scalar::UInt16: return static_cast<std::uint16_t>(v);
            case Scalar::Int32: return static_cast<std::int32_t>(v);
            case Scalar::UInt32: return static_cast<std::uint32_t>(v);
            case Scalar::Float32: return std::bit_cast<float>(static_cast<std::uint32_t>(v));
            case Scalar::Float64: return std::bit_cast<double>(v);
        }
        return 0.0;
    }

    // Past `n` numbers of type `t` without reading them (binary: a jump; ASCII: the tokens), with
    // read()'s message where the data ends first.
    void skip(Scalar t, std::uint64_t n) {
        if (format_ != Format::Ascii) {
            const std::uint64_t fit = std::min<std::uint64_t>(n, remaining() / scalar_size(t));
            pos_ += static_cast<std::size_t>(fit * scalar_size(t));
            if (fit < n) fail("the data ends early (a record is cut short)");  // at the first number cut
            return;
        }
        for (std::uint64_t i = 0; i < n; ++i) {
            skip_space();
            if (pos_ >= bytes_.size()) fail("the data ends early (fewer numbers than the header declares)");
            while (pos_ < bytes_.size() && bytes_[pos_] != ' ' && bytes_[pos_] != '\t' && bytes_[pos_] != '\r' && bytes_[pos_] != '\n')
                ++pos_;
        }
    }

private:
    void skip_space() {
        while (pos_ < bytes_.size()) {
            const char c = bytes_[pos_];
            if (c == '\n') ++line_;
            else if (c != ' ' && c != '\t' && c != '\r') break;
            ++pos_;
        }
    }

    double read_ascii(Scalar t) {
        skip_space();
        if (pos_ >= bytes_.size()) fail("the data ends early (fewer numbers than the header declares)");
        std::size_t end = pos_;
        while (end < bytes_.size() && bytes_[end] != ' ' && bytes_[end] != '\t' && bytes_[end] != '\r' && bytes_[end] != '\n') ++end;
        const std::string_view token = bytes_.substr(pos_, end - pos_);
        double v = 0.0;
        const char* first = token.data();
        if (!token.empty() && token[0] == '+') ++first;
        const auto [p, ec] = std::from_chars(first, token.data() + token.size(), v);
        if (ec != std::errc() || p != token.data() + token.size())
            fail("\"" + excerpt(token) + "\" is not a number");
        if (is_integer(t) && !(std::floor(v) == v && std::abs(v) < 4.3e9))
            fail("\"" + excerpt(token) + "\" is not an integer, as the property's type requires");
        pos_ = end;
        return v;
    }

    std::string_view bytes_;
    std::size_t pos_, line_;
    Format format_;
    const std::string& name_;
};

// The fewest bytes one record of `e` can take: a binary record's fixed part, or one character
// and a separator per ASCII number. Checked against what follows the header before anything is
// allocated, so a header cannot make the loader reserve more than the file could fill.
std::uint64_t min_record_bytes(const Element& e, Format f) {
    std::uint64_t n = 0;
    for (const Property& p : e.properties) {
        n += f == Format::Ascii ? 2 : scalar_size(p.list ? p.count_type : p.type);
    }
    return n;
}

struct VertexLayout {
    int x = -1, y = -1, z = -1, nx = -1, ny = -1, nz = -1, u = -1, v = -1;
};

VertexLayout vertex_layout(const Element& e, const std::string& name) {
    VertexLayout l;
    for (std::size_t i = 0; i < e.properties.size(); ++i) {
        const Property& p = e.properties[i];
        const int k = static_cast<int>(i);
        if (p.list) continue;  // no vertex property we read is a list
        if (p.name == "x") l.x = k;
        else if (p.name == "y") l.y = k;
        else if (p.name == "z") l.z = k;
        else if (p.name == "nx") l.nx = k;
        else if (p.name == "ny") l.ny = k;
        else if (p.name == "nz") l.nz = k;
        else if (p.name == "u" || p.name == "s" || p.name == "texture_u" || p.name == "texture_s") l.u = k;
        else if (p.name == "v" || p.name == "t" || p.name == "texture_v" || p.name == "texture_t") l.v = k;
    }
    if (l.x < 0 || l.y < 0 || l.z < 0)
        throw InputError(name + ": header line " + std::to_string(e.line) +
                         ": the vertex element needs properties x, y and z");
    if (l.nx < 0 || l.ny < 0 || l.nz < 0) l.nx = l.ny = l.nz = -1;
    if (l.u < 0 || l.v < 0) l.u = l.v = -1;
    return l;
}

struct PlyData {
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    std::vector<std::uint32_t> corners;        // every face's corners, in order
    std::vector<std::uint8_t> face_corners;    // corners per face
    std::vector<std::uint64_t> face_place;     // where each face starts (DataReader::place)
    bool normals_usable = true;
    bool has_faces = false;
};

void read_vertices(DataReader& r, const Element& e, PlyData& d, const std::string& name) {
    const VertexLayout l = vertex_layout(e, name);
    charge_load_memory(e.count * (sizeof(glm::vec3) + (l.nx >= 0 ? sizeof(glm::vec3) : 0) + (l.u >= 0 ? sizeof(glm::vec2) : 0)),
                       name, "element \"vertex\" (" + std::to_string(e.count) + " vertices)");
    d.positions.reserve(e.count);
    if (l.nx >= 0) d.normals.reserve(e.count);
    if (l.u >= 0) d.uvs.reserve(e.count);
    std::vector<double> values(e.properties.size());
    for (std::uint64_t i = 0; i < e.count; ++i) {
        for (std::size_t k = 0; k < e.properties.size(); ++k) {
            const Property& p = e.properties[k];
            if (p.list) {
                const double n = r.read(p.count_type);
                if (n < 0) r.fail("a negative list length");
                for (double j = 0; j < n; ++j) r.read(p.type);
                continue;
            }
            const std::uint64_t at = r.place();
            values[k] = r.read(p.type);
            const int ki = static_cast<int>(k);
            const bool needed = ki == l.x || ki == l.y || ki == l.z || ki == l.u || ki == l.v;
            if (needed && !std::isfinite(static_cast<float>(values[k])))
                throw InputError(name + ": " + r.where_label(at) + ": vertex " + std::to_string(i) + "'s " + excerpt(p.name) +
                                 " is not finite (as a float)");
        }
        d.positions.emplace_back(values[l.x], values[l.y], values[l.z]);
        if (l.nx >= 0) {
            const glm::dvec3 n(values[l.nx], values[l.ny], values[l.nz]);
            const double len = glm::length(n);
            if (!std::isfinite(len) || len == 0.0) d.normals_usable = false;
            else d.normals.push_back(glm::vec3(n / len));
        }
        if (l.u >= 0) d.uvs.emplace_back(values[l.u], values[l.v]);
    }
}

int face_list(const Element& e) {
    for (std::size_t k = 0; k < e.properties.size(); ++k)
        if (e.properties[k].list && (e.properties[k].name == "vertex_indices" || e.properties[k].name == "vertex_index"))
            return static_cast<int>(k);
    return -1;
}

// Face i's corner count `n`, read at `at`: 3 to kMaxCorners.
void check_corners(const DataReader& r, std::uint64_t at, std::uint64_t i, double n, const std::string& name) {
    if (n < 3 || n > kMaxCorners)
        throw InputError(name + ": " + r.where_label(at) + ": face " + std::to_string(i) + " has " + shown(n) +
                         " corners (a face has 3 to " + std::to_string(kMaxCorners) + ")");
}

struct FaceCounts {
    std::uint64_t corners = 0, triangles = 0;
};

// The face element's corners and the triangles they make, counted on a copy of the reader by the
// list lengths alone (the indices skipped), so both are charged before either is allocated and
// before the slow pass: 2,000,000 faces of 255 corners (a 2 MB .ply.gz) read 510 M corners into
// 2 GB for a minute before the 6 GB of triangles were refused.
FaceCounts count_faces(DataReader r, const Element& e, int list, const std::string& name) {
    FaceCounts c;
    for (std::uint64_t i = 0; i < e.count; ++i)
        for (std::size_t k = 0; k < e.properties.size(); ++k) {
            const Property& p = e.properties[k];
            if (!p.list) {
                r.skip(p.type, 1);
                continue;
            }
            const std::uint64_t at = r.place();
            const double n = r.read(p.count_type);
            if (static_cast<int>(k) == list) {
                check_corners(r, at, i, n, name);
                c.corners += static_cast<std::uint64_t>(n);
                c.triangles += static_cast<std::uint64_t>(n) - 2;
            } else if (n < 0) {
                r.fail("a negative list length");
            }
            r.skip(p.type, static_cast<std::uint64_t>(n));
        }
    return c;
}

void read_faces(DataReader& r, const Element& e, PlyData& d, const std::string& name) {
    const int list = face_list(e);
    if (list < 0)
        throw InputError(name + ": header line " + std::to_string(e.line) +
                         ": the face element needs a list property vertex_indices (or vertex_index)");
    d.has_faces = d.has_faces || e.count > 0;
    // The corners, their faces and the triangles they will make, charged at their exact sizes and
    // reserved once: grown by doubling, 2 GB of corners needed 3 GB while the vector moved.
    const FaceCounts counts = count_faces(r, e, list, name);
    charge_load_memory(e.count * (sizeof(std::uint8_t) + sizeof(std::uint64_t)) + counts.corners * sizeof(std::uint32_t) +
                           counts.triangles * sizeof(glm::uvec3),
                       name, std::to_string(e.count) + " faces as " + std::to_string(counts.triangles) + " triangles (" +
                                 std::to_string(counts.corners) + " corners)");
    d.face_corners.reserve(e.count);
    d.face_place.reserve(e.count);
    d.corners.reserve(counts.corners);
    for (std::uint64_t i = 0; i < e.count; ++i) {
        for (std::size_t k = 0; k < e.properties.size(); ++k) {
            const Property& p = e.properties[k];
            if (!p.list) {
                r.read(p.type);
                continue;
            }
            const std::uint64_t at = r.place();
            const double n = r.read(p.count_type);
            if (static_cast<int>(k) != list) {
                if (n < 0) r.fail("a negative list length");
                for (double j = 0; j < n; ++j) r.read(p.type);
                continue;
            }
            check_corners(r, at, i, n, name);
            for (int j = 0; j < static_cast<int>(n); ++j) {
                const std::uint64_t corner_at = r.place();
                const double v = r.read(p.type);
                // In range of the vertices is checked once all are read (they may follow the faces).
                if (!(v >= 0.0 && v <= 4294967294.0 && std::floor(v) == v))
                    throw InputError(name + ": " + r.where_label(corner_at) + ": face " + std::to_string(i) +
                                     " names vertex " + shown(v) + ", not a vertex index (0, 1, 2, ...)");
                d.corners.push_back(static_cast<std::uint32_t>(v));
            }
            d.face_corners.push_back(static_cast<std::uint8_t>(n));
            d.face_place.push_back(at);
        }
    }
}

void skip_element(DataReader& r, const Element& e) {
    if (e.properties.empty()) return;  // records of nothing: any count takes no bytes (nor time)
    for (std::uint64_t i = 0; i < e.count; ++i)
        for (const Property& p : e.properties) {
            if (!p.list) {
                r.read(p.type);
                continue;
            }
            const double n = r.read(p.count_type);
            if (n < 0) r.fail("a negative list length");
            for (double j = 0; j < n; ++j) r.read(p.type);
        }
}

}  // namespace

Mesh parse_ply(std::string_view bytes, const std::string& name) {
    const Header h = read_header(bytes, name);
    DataReader r(bytes, h, name);
    PlyData d;
    bool have_vertices = false;
    for (const Element& e : h.elements) {
        const std::uint64_t min = min_record_bytes(e, h.format);
        if (min > 0 && e.count > r.remaining() / min)
            throw InputError(name + ": header line " + std::to_string(e.line) + ": element \"" + excerpt(e.name) + "\" declares " +
                             std::to_string(e.count) + " records, more than the " + std::to_string(r.remaining()) +
                             " bytes after the header can hold");
        if (e.name == "vertex") {
            if (have_vertices) throw InputError(name + ": header line " + std::to_string(e.line) + ": a second vertex element");
            if (e.count > std::numeric_limits<std::uint32_t>::max())
                throw InputError(name + ": header line " + std::to_string(e.line) + ": more than 2^32 - 1 vertices");
            read_vertices(r, e, d, name);
            have_vertices = true;
        } else if (e.name == "face") {
            read_faces(r, e, d, name);
        } else {
            skip_element(r, e);
        }
    }
    if (!have_vertices) throw InputError(name + ": has no vertex element");
    if (!d.has_faces) throw InputError(name + ": contains no faces, nothing to render");

    const bool normals = !d.normals.empty() && d.normals_usable && d.normals.size() == d.positions.size();
    const bool uvs = d.uvs.size() == d.positions.size() && !d.uvs.empty();
    // A face of n corners is n - 2 triangles: a 255-corner face of uchar indices, 256 bytes of
    // binary PLY, is 253 triangles, 3 KB. Charged with the faces (read_faces), and reserved once:
    // growing by doubling would hold up to three times the final size. The mesh's own vertices
    // and the remap are charged here, once the vertices are known.
    std::uint64_t triangles = 0;
    for (const std::uint8_t n : d.face_corners) triangles += n - 2u;
    charge_load_memory(d.positions.size() * (sizeof(std::uint32_t) + sizeof(glm::vec3) + sizeof(glm::vec3) + sizeof(glm::vec2)),
                       name, std::to_string(d.positions.size()) + " vertices of the mesh");
    Mesh mesh;
    mesh.source = name;
    mesh.triangles.indices.reserve(triangles);
    std::vector<std::uint32_t> remap(d.positions.size(), std::numeric_limits<std::uint32_t>::max());
    auto vertex_for = [&](std::uint32_t v) {
        std::uint32_t& out = remap[v];
        if (out == std::numeric_limits<std::uint32_t>::max()) {
            out = static_cast<std::uint32_t>(mesh.triangles.vertices.size());
            mesh.triangles.vertices.push_back(d.positions[v]);
            if (normals) mesh.vertex_normals.push_back(d.normals[v]);
            if (uvs) mesh.vertex_uvs.push_back(d.uvs[v]);
        }
        return out;
    };
    std::size_t offset = 0;
    for (std::size_t f = 0; f < d.face_corners.size(); ++f) {
        const std::size_t n = d.face_corners[f];
        for (std::size_t k = 0; k < n; ++k)
            if (d.corners[offset + k] >= d.positions.size())
                throw InputError(name + ": " + r.where_label(d.face_place[f]) + ": face " + std::to_string(f) + " names vertex " +
                                 std::to_string(d.corners[offset + k]) + ", the file has " +
                                 std::to_string(d.positions.size()) + " (numbered from 0)");
        const std::uint32_t first = vertex_for(d.corners[offset]);
        std::uint32_t previous = vertex_for(d.corners[offset + 1]);
        for (std::size_t k = 2; k < n; ++k) {
            const std::uint32_t current = vertex_for(d.corners[offset + k]);
            mesh.triangles.indices.emplace_back(first, previous, current);
            previous = current;
        }
        offset += n;
    }
    return mesh;
}

Mesh load_ply(const std::filesystem::path& file) {
    return parse_ply(read_maybe_gzipped(file, "mesh", kMaxMeshFileBytes).bytes, file.string());
}

}  // namespace sweeptrace
