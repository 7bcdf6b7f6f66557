#pragma once
// Where a pbrt statement came from, and what the importer says about it: errors (malformed input,
// InputError "<file>:<line>: <what>; <fix>") and warnings for what it approximates or ignores.
// A warning is said once per kind (the first place it happens, with a count of the others), so a
// scene with 10,000 spheres of an unsupported kind gives one line, not 10,000. Under --strict the
// first warning is an error instead (exit 2, nothing written).
#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace sweeptrace::pbrt {

struct Where {
    std::shared_ptr<const std::string> file;  // as the user named it (or the Include resolved it)
    int line = 0;
    std::string text() const { return (file ? *file : std::string("?")) + ":" + std::to_string(line); }
    // The file's name without its folder: for names in the output that must not depend on how
    // the user spelled the path (material names).
    std::string short_text() const;
};

class Diagnostics {
public:
    explicit Diagnostics(bool strict) : strict_(strict) {}

    // Malformed input: throws InputError "<file>:<line>: <what>".
    [[noreturn]] void fail(const Where& where, const std::string& what) const;

    // Something not supported: `kind` groups repeats (e.g. "shape curve"); `what` says what was done
    // instead ("ignored", "approximated by ...").
    void warn(const Where& where, const std::string& kind, const std::string& what);

    // Under --strict, once the whole scene is read: throws InputError for the first warning (by
    // file and line), "<file>:<line>: <what> (--strict makes this an error)".
    void throw_if_strict() const;

    // One line per kind, by the file and line of its first place: "<file>:<line>: <what> (and N more)".
    std::vector<std::string> warnings() const;

private:
    struct Kind {
        Where where;
        std::string first;  // the message at its first place
        std::size_t repeats = 0;
    };
    bool strict_;
    std::map<std::string, std::size_t> index_;
    std::vector<Kind> kinds_;
};

}  // namespace sweeptrace::pbrt
