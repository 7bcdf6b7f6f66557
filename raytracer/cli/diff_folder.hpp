#pragma once
// `sweeptrace diff --golden DIR --actual DIR`: every golden image against the actual image of the
// same name, one verdict each, one exit code for all, and optional JSON, JUnit XML and HTML reports.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "raytracer/cli/diff_pair.hpp"

namespace sweeptrace {

struct FolderArgs {
    std::string golden, actual;       // directories
    std::string json, junit, html;    // optional report outputs (html: a directory)
    std::string variance_suffix = "-variance";  // NAME-variance.exr beside NAME.exr: the noise test
    std::string regenerate = "cp {actual} {golden}";  // shown per image in the HTML report
};

// One matched name and its outcome; `error` is set when the pair could not be compared (missing
// file, unreadable, sizes differ), and then `report` holds only the inputs.
struct FolderEntry {
    std::string name;
    PairReport report;
    std::string error;
    double seconds = 0.0;
    const char* status() const { return error.empty() ? report.status() : "ERROR"; }
};

void add_folder_options(CLI::App* cmd, FolderArgs& args);

// File names in the HTML report's folder for one image (the name keeps its extension so a.png and
// a.exr cannot collide): its panels ("golden", "actual", "heatmap") and its page.
inline std::string panel_file(const std::string& name, const char* panel) { return name + "." + panel + ".png"; }
inline std::string page_file(const std::string& name) { return name + ".html"; }

// Exit code: 2 if any pair could not be compared, else 1 if any failed, else 4 if any warned, else 0.
int run_diff_folders(const FolderArgs& args, const DiffSettings& settings);

// Report writers (diff_reports.cpp, diff_html.cpp); each writes atomically, throws InputError.
void write_json_report(const std::vector<FolderEntry>& entries, const FolderArgs& args, int exit_code);
void write_junit_report(const std::vector<FolderEntry>& entries, const FolderArgs& args);
void write_html_report(const std::vector<FolderEntry>& entries, const FolderArgs& args, const DiffSettings& settings);

}  // namespace sweeptrace
