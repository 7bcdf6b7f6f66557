#pragma once
// Reading a parsed JSON document while remembering where we are in it, so that every complaint
// names the file and the JSON path (`objects[3].radius`). Internal to the scene loader: it exposes
// nlohmann::json, which only raytracer/scene/*.cpp links against.
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

namespace sweeptrace::scene_json {

// Parses `text` (the contents of `file`). Invalid JSON and duplicate keys throw InputError naming
// the file with line and column (duplicates: with their JSON path).
nlohmann::json parse(const std::string& text, const std::filesystem::path& file);

// A value inside the document plus its path. Cheap to copy; refers to the document, which must
// outlive it.
class Node {
public:
    Node(const nlohmann::json& value, const std::filesystem::path& file, std::string path = {});

    const nlohmann::json& value() const { return *value_; }
    const std::string& path() const { return path_; }
    const std::filesystem::path& file() const { return *file_; }

    // Throws InputError "<file>: <path>: <message>".
    [[noreturn]] void fail(const std::string& message) const;

    // Object access. `require_object` also rejects any key not in `allowed`, naming that key's path.
    void require_object(std::initializer_list<std::string_view> allowed) const;
    void require_object(std::span<const std::string_view> allowed) const;
    bool has(std::string_view key) const;
    Node at(std::string_view key) const;  // missing key: "<path>.<key>: missing (required)"
    std::optional<Node> find(std::string_view key) const;

    // Array access.
    std::size_t array_size() const;  // fails unless an array
    Node element(std::size_t i) const;

    // Leaf values; each fails on the wrong JSON type or an out-of-range value.
    float number() const;  // finite, and finite once rounded to float
    float number_at_least(float lo, bool inclusive) const;
    float number_in(float lo, float hi) const;  // inclusive range
    std::int64_t integer(std::int64_t lo, std::int64_t hi) const;
    std::uint64_t unsigned_integer() const;
    std::string string() const;
    bool boolean() const;
    glm::vec3 vec3() const;                      // [x, y, z], each finite
    glm::vec3 vec3_at_least(float lo) const;     // each component >= lo
    glm::vec3 nonzero_vec3() const;              // not the zero vector (a direction)

    // The value as the user wrote it (roughly), for "got ..." in messages.
    std::string shown() const;

private:
    Node child(std::string_view key, const nlohmann::json& v) const;

    const nlohmann::json* value_;
    const std::filesystem::path* file_;
    std::string path_;
};

// Numbers in messages as people write them: 0, 1, 1.5 (not 0.0, 1.0).
std::string format_number(float f);

// A key's step of a path in messages: `parent.key`, or `parent["a key"]` when the key is not
// plain letters, digits, '_' and '-' (the pbrt importer matches its material names with it).
std::string key_component(const std::string& parent, std::string_view key);

// "a number", "a string", "an array", ... for messages about the wrong type.
std::string describe_type(const nlohmann::json& v);

}  // namespace sweeptrace::scene_json
