#include "raytracer/scene/pbrt/pbrt_diagnostics.hpp"

#include <algorithm>
#include <filesystem>

#include "raytracer/input_error.hpp"

namespace sweeptrace::pbrt {

std::string Where::short_text() const {
    return (file ? std::filesystem::path(*file).filename().string() : std::string("?")) + ":" + std::to_string(line);
}

void Diagnostics::fail(const Where& where, const std::string& what) const { throw InputError(where.text() + ": " + what); }

void Diagnostics::warn(const Where& where, const std::string& kind, const std::string& what) {
    if (auto it = index_.find(kind); it != index_.end()) {
        ++kinds_[it->second].repeats;
        return;
    }
    index_.emplace(kind, kinds_.size());
    kinds_.push_back({where, escape_control(where.text() + ": " + what), 0});  // a pbrt string may hold ESC or a newline
}

void Diagnostics::throw_if_strict() const {
    if (strict_ && !kinds_.empty()) {
        std::string first = warnings().front();
        if (const std::size_t more = first.rfind(" (and "); more != std::string::npos) first.resize(more);
        throw InputError(first + " (--strict makes this an error)");
    }
}

std::vector<std::string> Diagnostics::warnings() const {
    std::vector<const Kind*> order;
    for (const Kind& k : kinds_) order.push_back(&k);
    // Files in the order they were first warned about, lines in order within each.
    std::map<std::string, std::size_t> file_rank;
    for (const Kind& k : kinds_) file_rank.emplace(k.where.file ? *k.where.file : std::string(), file_rank.size());
    std::stable_sort(order.begin(), order.end(), [&](const Kind* a, const Kind* b) {
        const std::size_t fa = file_rank[a->where.file ? *a->where.file : std::string()];
        const std::size_t fb = file_rank[b->where.file ? *b->where.file : std::string()];
        return fa != fb ? fa < fb : a->where.line < b->where.line;
    });
    std::vector<std::string> out;
    out.reserve(kinds_.size());
    for (const Kind* kp : order)
        out.push_back(kp->repeats == 0 ? kp->first : kp->first + " (and " + std::to_string(kp->repeats) + " more like it)");
    return out;
}

}  // namespace sweeptrace::pbrt
