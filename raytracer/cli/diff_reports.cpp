// JSON and JUnit XML reports of folder mode. JUnit: one <testcase> per golden image; a failed
// verdict is a <failure>, a pair that could not be compared an <error>, warnings go to
// <system-out> (the schema Jenkins and GitLab read).
#include <cmath>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "raytracer/cli/diff_folder.hpp"
#include "raytracer/cli/report_text.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace {
namespace {


// JSON numbers cannot be inf or nan: those become strings.
nlohmann::json number(double v) {
    if (std::isfinite(v)) return v;
    return number_text(v);
}

nlohmann::json entry_json(const FolderEntry& e) {
    nlohmann::json j{{"name", e.name}, {"status", e.status()}, {"actual", e.report.inputs.a},
                     {"golden", e.report.inputs.b}, {"seconds", e.seconds}};
    if (!e.error.empty()) {
        j["error"] = e.error;
        return j;
    }
    const PairReport& r = e.report;
    const DiffMetrics& m = r.metrics;
    j["metrics"] = {{"width", m.width}, {"height", m.height}, {"rmse", number(m.rmse)}, {"psnr", number(m.psnr)},
                    {"psnr_peak", number(m.psnr_peak)}, {"mean_abs", number(m.mean_abs)},
                    {"max_abs", number(m.max_abs)}, {"max_abs_at", {m.max_x, m.max_y}},
                    {"share_over_threshold", number(m.share_over)}, {"mean_delta_e", number(m.mean_delta_e)},
                    {"non_finite_actual", m.non_finite_a}, {"non_finite_golden", m.non_finite_b}};
    const FlipResult& f = r.flip;
    j["flip"] = {{"mode", f.exposures > 0 ? "hdr" : "ldr"}, {"mean", number(f.mean)},
                 {"weighted_median", number(f.weighted_median)},
                 {"weighted_first_quartile", number(f.weighted_first_quartile)},
                 {"weighted_third_quartile", number(f.weighted_third_quartile)}, {"max", number(f.max)},
                 {"max_at", {f.max_x, f.max_y}}, {"worst_3x3_mean", number(r.flip_local)}};
    if (f.exposures > 0)
        j["flip"]["exposures"] = {{"start", f.start_exposure}, {"stop", f.stop_exposure}, {"count", f.exposures}};
    if (r.alpha_present) j["alpha_max_difference"] = r.alpha_max_difference;
    if (r.noise)
        j["noise_test"] = {{"max_z", number(r.noise->max_z)}, {"z_limit", number(r.noise->z_limit)},
                           {"blocks_tested", r.noise->blocks_tested}, {"blocks_over", r.noise->blocks_over},
                           {"variance_actual", r.inputs.variance_a}, {"variance_golden", r.inputs.variance_b}};
    j["failures"] = r.failures;
    j["warnings"] = r.warnings;
    return j;
}


std::string joined(const std::vector<std::string>& items) {
    std::string out;
    for (const auto& i : items) out += (out.empty() ? "" : "; ") + i;
    return out;
}

}  // namespace

void write_json_report(const std::vector<FolderEntry>& entries, const FolderArgs& args, int exit_code) {
    nlohmann::json j{{"tool", "sweeptrace diff"}, {"golden", args.golden}, {"actual", args.actual},
                     {"exit_code", exit_code}, {"images", nlohmann::json::array()}};
    for (const FolderEntry& e : entries) j["images"].push_back(entry_json(e));
    write_text_file(args.json, j.dump(2) + "\n");
}

void write_junit_report(const std::vector<FolderEntry>& entries, const FolderArgs& args) {
    int failures = 0, errors = 0;
    double seconds = 0.0;
    for (const FolderEntry& e : entries) {
        failures += e.error.empty() && !e.report.failures.empty();
        errors += !e.error.empty();
        seconds += e.seconds;
    }
    std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    x += "<testsuites name=\"sweeptrace diff\" tests=\"" + std::to_string(entries.size()) + "\" failures=\"" +
         std::to_string(failures) + "\" errors=\"" + std::to_string(errors) + "\" time=\"" + number_text(seconds) + "\">\n";
    x += "  <testsuite name=\"" + markup_escape(args.golden) + "\" tests=\"" + std::to_string(entries.size()) +
         "\" failures=\"" + std::to_string(failures) + "\" errors=\"" + std::to_string(errors) +
         "\" skipped=\"0\" time=\"" + number_text(seconds) + "\">\n";
    for (const FolderEntry& e : entries) {
        x += "    <testcase classname=\"sweeptrace.diff\" name=\"" + markup_escape(e.name) + "\" time=\"" +
             number_text(e.seconds) + "\">\n";
        if (!e.error.empty())
            x += "      <error message=\"" + markup_escape(e.error) + "\" type=\"input\"/>\n";
        else if (!e.report.failures.empty())
            x += "      <failure message=\"" + markup_escape(joined(e.report.failures)) + "\" type=\"over tolerance\">" +
                 markup_escape("FLIP mean " + number_text(e.report.flip.mean) + ", RMSE " + number_text(e.report.metrics.rmse)) +
                 "</failure>\n";
        if (e.error.empty())
            x += "      <system-out>" + markup_escape(std::string(e.status()) + ": FLIP mean " + number_text(e.report.flip.mean) +
                                               (e.report.warnings.empty() ? "" : "; warning: " + joined(e.report.warnings))) +
                 "</system-out>\n";
        x += "    </testcase>\n";
    }
    x += "  </testsuite>\n</testsuites>\n";
    write_text_file(args.junit, x);
}

}  // namespace sweeptrace
