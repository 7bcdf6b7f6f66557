#include "raytracer/cli/diff_folder.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <set>
#include <utility>
#include <vector>

#include "raytracer/cli/output_guard.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace {
namespace {

namespace fs = std::filesystem;

bool is_image_name(const fs::path& p) {
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext == ".png" || ext == ".pfm" || ext == ".exr";
}

bool is_variance_name(const fs::path& p, const std::string& suffix) {
    const std::string stem = p.stem().string();
    return !suffix.empty() && stem.size() > suffix.size() && stem.ends_with(suffix);
}

// Image names in `dir`, variance files left out, sorted.
std::set<std::string> image_names(const std::string& dir, const std::string& suffix, const char* role) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw InputError(std::string(role) + " '" + dir + "' is not a directory");
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.is_regular_file() && is_image_name(e.path()) && !is_variance_name(e.path(), suffix))
            names.insert(e.path().filename().string());
    return names;
}

// NAME-variance.exr (or .pfm) beside NAME.ext, if there is one.
std::string variance_of(const std::string& dir, const std::string& name, const std::string& suffix) {
    const std::string stem = fs::path(name).stem().string();
    for (const char* ext : {".exr", ".pfm"}) {
        const fs::path p = fs::path(dir) / (stem + suffix + ext);
        if (fs::exists(p)) return p.string();
    }
    return "";
}

FolderEntry compare_entry(const std::string& name, const FolderArgs& args, const DiffSettings& settings) {
    FolderEntry e;
    e.name = name;
    PairInputs in{(fs::path(args.actual) / name).string(), (fs::path(args.golden) / name).string(), "", ""};
    e.report.inputs = in;
    const auto start = std::chrono::steady_clock::now();
    try {
        if (!fs::exists(in.a)) throw InputError("no actual image '" + in.a + "' for golden '" + in.b + "'");
        const std::string va = variance_of(args.actual, name, args.variance_suffix);
        const std::string vb = variance_of(args.golden, name, args.variance_suffix);
        if (!va.empty() && !vb.empty()) {
            in.variance_a = va;
            in.variance_b = vb;
        }
        e.report = compare_pair(in, settings);
    } catch (const InputError& error) {
        e.error = error.what();
    }
    e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return e;
}

int aggregate(const std::vector<FolderEntry>& entries) {
    int code = diff_exit_pass;
    for (const FolderEntry& e : entries) {
        const int c = e.error.empty() ? e.report.exit_code() : diff_exit_bad_input;
        auto rank = [](int x) { return x == diff_exit_bad_input ? 3 : x == diff_exit_fail ? 2 : x == diff_exit_warn ? 1 : 0; };
        if (rank(c) > rank(code)) code = c;
    }
    return code;
}

// Every file folder mode writes, for the one output rule (output_guard.hpp): the reports and,
// when the HTML folder exists already, each page and panel it would get (a new folder holds no
// input); and every file it reads, the images and their variances.
void check_folder_outputs(const FolderArgs& args, const std::set<std::string>& golden) {
    std::vector<NamedFile> outputs{{"--json", args.json}, {"--junit", args.junit}};
    if (!args.html.empty()) {
        std::error_code ec;
        const fs::path dir(args.html);
        if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
            throw InputError("--html '" + args.html + "' " + file_kind_problem(dir) + ": the HTML report is a folder");
        if (!fs::is_directory(dir, ec)) {
            const fs::path parent = fs::absolute(dir).parent_path();
            if (!fs::is_directory(parent, ec))
                throw InputError("--html '" + args.html + "': directory '" + parent.string() + "' does not exist");
        } else {
            outputs.push_back({"--html", dir / "index.html"});
            for (const std::string& name : golden) {
                outputs.push_back({"--html page", dir / page_file(name)});
                for (const char* panel : {"golden", "actual", "heatmap"}) outputs.push_back({"--html panel", dir / panel_file(name, panel)});
            }
        }
    }
    std::vector<NamedFile> inputs;
    for (const auto& [role, folder] : {std::pair{"--golden image", args.golden}, std::pair{"--actual image", args.actual}})
        for (const auto& e : fs::directory_iterator(folder))
            if (e.is_regular_file()) inputs.push_back({role, e.path()});
    check_outputs(outputs, inputs);
}

}  // namespace

void add_folder_options(CLI::App* cmd, FolderArgs& a) {
    cmd->add_option("--golden", a.golden, "Folder mode: directory of reference images (matched to --actual by name)");
    cmd->add_option("--actual", a.actual, "Folder mode: directory of images under test");
    cmd->add_option("--json", a.json, "Folder mode: write every verdict and metric as JSON");
    cmd->add_option("--junit", a.junit, "Folder mode: write JUnit XML (one testcase per image)");
    cmd->add_option("--html", a.html, "Folder mode: write an HTML report (index + golden | actual | heatmap pages) into DIR");
    cmd->add_option("--variance-suffix", a.variance_suffix,
                    "Folder mode: NAME<suffix>.exr beside NAME in both folders turns on the noise test for NAME")
        ->capture_default_str();
    cmd->add_option("--regenerate", a.regenerate,
                    "Folder mode: command shown in the HTML report to regenerate a golden ({golden}, {actual}, {name})")
        ->capture_default_str();
}

int run_diff_folders(const FolderArgs& args, const DiffSettings& settings) {
    if (args.golden.empty() || args.actual.empty()) throw InputError("folder mode needs both --golden DIR and --actual DIR");
    const std::set<std::string> golden = image_names(args.golden, args.variance_suffix, "--golden");
    const std::set<std::string> actual = image_names(args.actual, args.variance_suffix, "--actual");
    if (golden.empty()) throw InputError("--golden '" + args.golden + "' holds no .png, .pfm or .exr images");
    check_folder_outputs(args, golden);
    std::vector<FolderEntry> entries;
    for (const std::string& name : golden) {
        entries.push_back(compare_entry(name, args, settings));
        const FolderEntry& e = entries.back();
        if (e.error.empty()) print_report(e.report, stdout);
        else std::printf("%s: ERROR: %s\n", name.c_str(), e.error.c_str());
    }
    for (const std::string& name : actual)
        if (!golden.count(name)) std::printf("%s: no golden (not compared)\n", name.c_str());
    const int code = aggregate(entries);
    std::printf("\n%-32s %s\n", "image", "verdict");
    for (const FolderEntry& e : entries) std::printf("%-32s %s\n", e.name.c_str(), e.status());
    std::printf("%zu images, exit %d\n", entries.size(), code);
    try {
        if (!args.json.empty()) write_json_report(entries, args, code);
        if (!args.junit.empty()) write_junit_report(entries, args);
        if (!args.html.empty()) write_html_report(entries, args, settings);
    } catch (const InputError& e) {  // the verdicts are printed; a failure keeps its exit code
        std::fprintf(stderr, "sweeptrace: error: %s\n", e.what());
        return code == diff_exit_fail ? diff_exit_fail : diff_exit_bad_input;
    }
    return code;
}

}  // namespace sweeptrace
