#include "raytracer/accuracy/report.hpp"

#include <cstdio>
#include <fstream>
#include <string>

#include "raytracer/image/atomic_file.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace::accuracy {
namespace {

std::string number(double v, const char* format = "%.3g") {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

double rate(std::size_t count, std::size_t of) { return of ? double(count) / double(of) : 0.0; }

}  // namespace

void write_csv(std::ostream& out, const std::vector<Metrics>& rows) {
    out << "shape,variant,family,rays,boundary,within_rounding,wrong,wrong_rate,wrong_clear,wrong_clear_rate,false_hits,t_scored,t_rel_median,t_rel_p99,"
           "t_rel_max,self_hits,self_hit_rate,leaks,leak_rate,mrays_per_s\n";
    for (const Metrics& m : rows) {
        out << m.shape << ',' << m.variant << ',' << m.family << ',' << m.rays << ',' << m.boundary << ','
            << m.within_rounding << ',' << m.wrong << ',' << number(m.wrong_rate(), "%.6g") << ',' << m.wrong_clear << ','
            << number(m.wrong_clear_rate(), "%.6g") << ',' << m.false_hits << ',' << m.t_scored << ','
            << number(m.t_median, "%.6g") << ',' << number(m.t_p99, "%.6g") << ',' << number(m.t_max, "%.6g") << ','
            << m.self_hits << ',' << number(rate(m.self_hits, m.rays), "%.6g") << ',' << m.leaks << ','
            << number(rate(m.leaks, m.rays), "%.6g") << ',' << number(m.mrays_per_s(), "%.4g") << '\n';
    }
}

void write_markdown(std::ostream& out, const std::vector<Metrics>& rows) {
    out << "| shape | variant | family | rays | exact touch | within rounding | wrong hit/miss | wrong beyond rounding "
           "| t rel. err. median | p99 | max | self-hits | leaks | Mrays/s |\n";
    out << "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const Metrics& m : rows) {
        out << "| " << m.shape << " | " << m.variant << " | " << m.family << " | " << m.rays << " | " << m.boundary
            << " | " << m.within_rounding << " | " << m.wrong << " (" << number(100.0 * m.wrong_rate()) << "%) | "
            << m.wrong_clear << " | " << number(m.t_median) << " | "
            << number(m.t_p99) << " | " << number(m.t_max) << " | " << m.self_hits << " | " << m.leaks << " | "
            << (m.seconds > 0.0 ? number(m.mrays_per_s()) : std::string("-")) << " |\n";
    }
}

void save_file(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write) {
    write_atomically(path, [&](const std::filesystem::path& temp) {
        std::ofstream f(temp, std::ios::binary | std::ios::trunc);
        if (!f) throw InputError("cannot write '" + path.string() + "'");
        write(f);
        f.flush();
        if (!f) throw InputError("cannot write '" + path.string() + "': write failed");
    });
}

void check_writable(const std::filesystem::path& path) {
    const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    if (!std::filesystem::is_directory(dir)) throw InputError(path.string() + ": directory " + dir.string() + " does not exist");
    if (std::filesystem::is_directory(path)) throw InputError(path.string() + ": is a directory");
}

}  // namespace sweeptrace::accuracy
