#include "raytracer/scene/json_reader.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <vector>

#include "raytracer/input_error.hpp"

namespace sweeptrace::scene_json {

namespace {

// Keys that are plain identifiers print as `.key`; anything else as `["key"]` so the path stays
// unambiguous for material names with spaces or dots.

// The path is quoted as an excerpt: a key may be any string, and the message stays one short line.
std::string where(const std::filesystem::path& file, const std::string& path) {
    return file.string() + ": " + (path.empty() ? std::string("(top level)") : excerpt(path, 120)) + ": ";
}

// Deeper than any scene needs (root > objects > object > transform > step > rotate > axis is 6),
// and shallow enough that nothing recursive over the document (dump, destruction, messages) can
// run out of stack. Checked on the raw text, before nlohmann builds anything.
constexpr int kMaxNesting = 32;

// Byte offset of the first bracket that opens level kMaxNesting + 1, or npos.
std::size_t too_deep_at(const std::string& text) {
    int depth = 0;
    bool in_string = false, escaped = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (in_string) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxNesting) return i;
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return std::string::npos;
}

// JSON text of `v`, cut off after about `budget` bytes, without serialising all of a huge value.
void bounded_dump(const nlohmann::json& v, std::size_t budget, std::string& out) {
    constexpr auto kReplace = nlohmann::json::error_handler_t::replace;  // never throw over a cut character
    if (!v.is_structured()) {
        out += v.dump(-1, ' ', false, kReplace);
        return;
    }
    const bool object = v.is_object();
    out += object ? '{' : '[';
    bool first = true;
    for (auto it = v.begin(); it != v.end(); ++it) {
        if (out.size() >= budget) {
            out += "...";
            break;
        }
        if (!first) out += ", ";
        first = false;
        if (object) out += nlohmann::json(excerpt(it.key(), budget)).dump(-1, ' ', false, kReplace) + ": ";
        bounded_dump(*it, budget, out);
    }
    out += object ? '}' : ']';
}

// nlohmann reports the byte offset of the character it stopped at; people want line:column.
std::pair<std::size_t, std::size_t> line_column(const std::string& text, std::size_t byte) {
    const std::size_t off = std::min(byte > 0 ? byte - 1 : 0, text.size());
    std::size_t line = 1, line_start = 0;
    for (std::size_t i = 0; i < off; ++i)
        if (text[i] == '\n') {
            ++line;
            line_start = i + 1;
        }
    return {line, off - line_start + 1};
}

// Strips nlohmann's "[json.exception.parse_error.101] parse error at line 1, column 2: " prefix,
// keeping its description of what went wrong.
std::string parse_error_reason(const std::string& what) {
    const std::size_t column = what.find("column ");
    if (column != std::string::npos) {
        const std::size_t colon = what.find(": ", column);
        if (colon != std::string::npos) return what.substr(colon + 2);
    }
    const std::size_t bracket = what.find("] ");
    return bracket != std::string::npos ? what.substr(bracket + 2) : what;
}

// nlohmann keeps the last of duplicate keys silently; a scene with "radius" twice is a mistake
// the user should hear about. This tracks the JSON path during parsing to name the duplicate.
class DuplicateKeyCheck {
public:
    explicit DuplicateKeyCheck(const std::filesystem::path& file) : file_(&file) {}

    bool operator()(int /*depth*/, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
        using E = nlohmann::json::parse_event_t;
        switch (event) {
        case E::object_start:
        case E::array_start:
            count_element();
            frames_.push_back(OpenContainer{event == E::object_start, {}, {}, 0});
            break;
        case E::object_end:
        case E::array_end:
            frames_.pop_back();
            break;
        case E::key: {
            OpenContainer& top = frames_.back();
            std::string key = parsed.get<std::string>();
            if (!top.keys.insert(key).second)
                throw InputError(where(*file_, key_component(container_path(), key)) +
                                 "duplicate key (each key may appear once)");
            top.key = std::move(key);
            break;
        }
        case E::value:
            count_element();
            break;
        }
        return true;
    }

private:
    struct OpenContainer {
        bool object;
        std::set<std::string> keys;
        std::string key;         // object: the key being read
        std::size_t next_index;  // array: elements seen so far
    };

    void count_element() {
        if (!frames_.empty() && !frames_.back().object) ++frames_.back().next_index;
    }

    // Path of the innermost open container (the frames below it say how we got there).
    std::string container_path() const {
        std::string path;
        for (std::size_t i = 0; i + 1 < frames_.size(); ++i) {
            const OpenContainer& f = frames_[i];
            if (f.object)
                path = key_component(path, f.key);
            else
                path += "[" + std::to_string(f.next_index - 1) + "]";
        }
        return path;
    }

    const std::filesystem::path* file_;
    std::vector<OpenContainer> frames_;
};

}  // namespace

std::string key_component(const std::string& parent, std::string_view key) {
    const bool plain = !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
    });
    if (plain) return parent.empty() ? std::string(key) : parent + "." + std::string(key);
    return parent + "[" + nlohmann::json(std::string(key)).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "]";
}

nlohmann::json parse(const std::string& text, const std::filesystem::path& file) {
    if (const std::size_t at = too_deep_at(text); at != std::string::npos) {
        const auto [line, column] = line_column(text, at + 1);
        throw InputError(file.string() + ":" + std::to_string(line) + ":" + std::to_string(column) +
                         ": nested deeper than " + std::to_string(kMaxNesting) + " arrays/objects (no scene needs more than 6)");
    }
    try {
        return nlohmann::json::parse(text, DuplicateKeyCheck(file));
    } catch (const nlohmann::json::parse_error& e) {
        const auto [line, column] = line_column(text, e.byte);
        throw InputError(file.string() + ":" + std::to_string(line) + ":" + std::to_string(column) +
                         ": invalid JSON: " + excerpt(reason_or(parse_error_reason(e.what()).c_str(), "parse error"), 160));
    } catch (const nlohmann::json::out_of_range& e) {
        // Number overflow (1e999): nlohmann names the token but not its place; find it.
        const std::string what = e.what();
        const std::size_t open = what.find('\'');
        const std::size_t close = open == std::string::npos ? open : what.find('\'', open + 1);
        std::string token, place;
        if (close != std::string::npos) {
            token = what.substr(open + 1, close - open - 1);
            const std::size_t at = text.find(token);
            if (at != std::string::npos) {
                const auto [line, column] = line_column(text, at + 1);
                place = ":" + std::to_string(line) + ":" + std::to_string(column);
            }
        }
        throw InputError(file.string() + place + ": number " + (token.empty() ? std::string() : excerpt(token, 40) + " ") +
                         "is out of range (not a finite double)");
    }
}

std::string format_number(float f) {
    std::ostringstream s;
    s << f;
    return s.str();
}

std::string describe_type(const nlohmann::json& v) {
    switch (v.type()) {
    case nlohmann::json::value_t::null: return "null";
    case nlohmann::json::value_t::object: return "an object";
    case nlohmann::json::value_t::array: return "an array";
    case nlohmann::json::value_t::string: return "a string";
    case nlohmann::json::value_t::boolean: return "a boolean";
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
    case nlohmann::json::value_t::number_float: return "a number";
    default: return "an unsupported value";
    }
}

Node::Node(const nlohmann::json& value, const std::filesystem::path& file, std::string path)
    : value_(&value), file_(&file), path_(std::move(path)) {}

void Node::fail(const std::string& message) const { throw InputError(where(*file_, path_) + message); }

std::string Node::shown() const {
    // nlohmann prints a non-finite number as "null": a translated pbrt value that overflowed.
    if (value_->is_number_float())
        if (const double d = value_->get<double>(); !std::isfinite(d)) return std::isnan(d) ? "nan" : d > 0 ? "inf" : "-inf";
    std::string s;
    bounded_dump(*value_, 40, s);
    return excerpt(s, 40);
}

Node Node::child(std::string_view key, const nlohmann::json& v) const {
    return Node(v, *file_, key_component(path_, key));
}

void Node::require_object(std::initializer_list<std::string_view> allowed) const {
    require_object(std::span<const std::string_view>(allowed.begin(), allowed.size()));
}

void Node::require_object(std::span<const std::string_view> allowed) const {
    if (!value_->is_object()) fail("must be an object, got " + describe_type(*value_));
    for (const auto& [key, v] : value_->items()) {
        if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
        std::string list;
        for (std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
        child(key, v).fail("unknown key (allowed here: " + list + ")");
    }
}

bool Node::has(std::string_view key) const {
    return value_->is_object() && value_->contains(std::string(key));
}

Node Node::at(std::string_view key) const {
    if (!value_->is_object()) fail("must be an object, got " + describe_type(*value_));
    const auto it = value_->find(std::string(key));
    if (it == value_->end()) throw InputError(where(*file_, key_component(path_, key)) + "missing (required)");
    return child(key, *it);
}

std::optional<Node> Node::find(std::string_view key) const {
    if (!has(key)) return std::nullopt;
    return at(key);
}

std::size_t Node::array_size() const {
    if (!value_->is_array()) fail("must be an array, got " + describe_type(*value_));
    return value_->size();
}

Node Node::element(std::size_t i) const {
    return Node(value_->at(i), *file_, path_ + "[" + std::to_string(i) + "]");
}

float Node::number() const {
    if (!value_->is_number()) fail("must be a number, got " + describe_type(*value_));
    const double d = value_->get<double>();
    if (!std::isfinite(d)) fail("must be a finite number, got " + shown());
    const float f = static_cast<float>(d);
    if (!std::isfinite(f)) fail("is too large for single precision, got " + shown());
    return f;
}

float Node::number_at_least(float lo, bool inclusive) const {
    const float f = number();
    if (inclusive ? !(f >= lo) : !(f > lo))
        fail(std::string("must be ") + (inclusive ? ">= " : "> ") + format_number(lo) + ", got " + shown());
    return f;
}

float Node::number_in(float lo, float hi) const {
    const float f = number();
    if (!(f >= lo && f <= hi))
        fail("must be in [" + format_number(lo) + ", " + format_number(hi) + "], got " + shown());
    return f;
}

std::int64_t Node::integer(std::int64_t lo, std::int64_t hi) const {
    if (!value_->is_number_integer()) fail("must be an integer, got " + (value_->is_number() ? shown() : describe_type(*value_)));
    if (value_->is_number_unsigned() && value_->get<std::uint64_t>() > static_cast<std::uint64_t>(hi))
        fail("must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + shown());
    const std::int64_t i = value_->get<std::int64_t>();
    if (i < lo || i > hi) fail("must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + shown());
    return i;
}

std::uint64_t Node::unsigned_integer() const {
    if (!value_->is_number_integer()) fail("must be an integer, got " + (value_->is_number() ? shown() : describe_type(*value_)));
    if (!value_->is_number_unsigned()) fail("must be >= 0, got " + shown());
    return value_->get<std::uint64_t>();
}

std::string Node::string() const {
    if (!value_->is_string()) fail("must be a string, got " + describe_type(*value_));
    return value_->get<std::string>();
}

bool Node::boolean() const {
    if (!value_->is_boolean()) fail("must be true or false, got " + describe_type(*value_));
    return value_->get<bool>();
}

glm::vec3 Node::vec3() const {
    if (!value_->is_array() || value_->size() != 3)
        fail("must be an array of 3 numbers [x, y, z], got " + (value_->is_array() ? shown() : describe_type(*value_)));
    return {element(0).number(), element(1).number(), element(2).number()};
}

glm::vec3 Node::vec3_at_least(float lo) const {
    const glm::vec3 v = vec3();
    for (int i = 0; i < 3; ++i)
        if (!(v[i] >= lo)) element(static_cast<std::size_t>(i)).number_at_least(lo, true);
    return v;
}

glm::vec3 Node::nonzero_vec3() const {
    const glm::vec3 v = vec3();
    if (v == glm::vec3(0.0f)) fail("must not be the zero vector");
    return v;
}

}  // namespace sweeptrace::scene_json
