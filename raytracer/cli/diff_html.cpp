// The HTML report of folder mode: DIR/index.html (one row per image with thumbnails) and one page
// per image with golden | actual | FLIP heatmap side by side, a colour legend, the metrics and
// the command that regenerates the golden. Pages fit a 1400-pixel-wide window (panels share the
// width, images scale with it, pixelated so single-pixel defects stay visible). Float images are
// shown clamped to [0, 1] and sRGB-encoded (no tone mapping), as PNG copies beside the pages.
#include <filesystem>
#include <fstream>
#include <string>

#include "raytracer/cli/diff_folder.hpp"
#include "raytracer/cli/report_text.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace {
namespace {

namespace fs = std::filesystem;




std::string replace_all(std::string s, const std::string& key, const std::string& value) {
    for (std::size_t at = s.find(key); at != std::string::npos; at = s.find(key, at + value.size()))
        s.replace(at, key.size(), value);
    return s;
}

const char* style =
    "<style>body{margin:0 auto;padding:12px;max-width:1400px;box-sizing:border-box;font:14px sans-serif;"
    "background:#fff;color:#111}h1{font-size:20px;margin:0 0 8px}.panels{display:flex;gap:8px}"
    "figure{margin:0;flex:1 1 0;min-width:0}figure img{display:block;width:100%;height:auto;"
    "image-rendering:pixelated}figcaption{font-weight:bold;padding:2px 0}"
    ".legend{height:14px;margin-top:8px;background:linear-gradient(to right,#000,#00f,#0ff,#0f0,#ff0,#f00)}"
    ".scale{position:relative;height:18px}.scale span{position:absolute;transform:translateX(-50%)}"
    ".scale span:first-child{transform:none}.scale span:last-child{transform:translateX(-100%)}.pass{color:#070}.FAIL,.ERROR{color:#b00}.WARN{color:#a60}"
    "table{border-collapse:collapse}td,th{padding:2px 8px;text-align:left;vertical-align:middle}"
    "code{background:#eee;padding:2px 4px}</style>";

std::string metrics_rows(const PairReport& r) {
    const DiffMetrics& m = r.metrics;
    const FlipResult& f = r.flip;
    std::string t = "<table>";
    auto row = [&t](const std::string& k, const std::string& v) { t += "<tr><th>" + k + "</th><td>" + v + "</td></tr>"; };
    row(f.exposures > 0 ? "HDR-FLIP mean" : "FLIP mean", number_text(f.mean));
    row("FLIP weighted median / quartiles", number_text(f.weighted_median) + " / " + number_text(f.weighted_first_quartile) +
                                                " .. " + number_text(f.weighted_third_quartile));
    row("FLIP max", number_text(f.max) + " at (" + std::to_string(f.max_x) + ", " + std::to_string(f.max_y) + ")");
    row("FLIP worst 3x3 mean", number_text(r.flip_local));
    row("RMSE", number_text(m.rmse));
    row("PSNR", number_text(m.psnr) + " dB (peak " + number_text(m.psnr_peak) + ")");
    row("max |a-b|", number_text(m.max_abs));
    if (r.noise) row("noise test", markup_escape(r.noise->summary()));
    for (const auto& f2 : r.failures) row("over", markup_escape(f2));
    for (const auto& w : r.warnings) row("warning", markup_escape(w));
    return t + "</table>";
}

void write_page(const FolderEntry& e, const FolderArgs& args, const fs::path& dir) {
    const PairReport& r = e.report;
    write_image(read_image(r.inputs.b), dir / panel_file(e.name, "golden"));
    write_image(read_image(r.inputs.a), dir / panel_file(e.name, "actual"));
    write_image(flip_heatmap(r.flip), dir / panel_file(e.name, "heatmap"));
    std::string cmd = replace_all(args.regenerate, "{golden}", fs::absolute(r.inputs.b).string());
    cmd = replace_all(cmd, "{actual}", fs::absolute(r.inputs.a).string());
    cmd = replace_all(cmd, "{name}", e.name);
    std::string h = "<!doctype html><html><head><meta charset=\"utf-8\"><title>" + markup_escape(e.name) + ": " +
                    e.status() + "</title>" + style + "</head><body>";
    h += "<h1>" + markup_escape(e.name) + ": <span class=\"" + e.status() + "\">" + e.status() + "</span></h1>";
    h += "<p><a href=\"index.html\">all images</a></p><div class=\"panels\">";
    for (const auto& [panel, caption] : {std::pair{"golden", "golden (reference)"}, {"actual", "actual"},
                                         {"heatmap", "FLIP heatmap"}})
        h += "<figure><figcaption>" + std::string(caption) + "</figcaption><img src=\"" +
             markup_escape(panel_file(e.name, panel)) + "\" alt=\"" + panel + "\"></figure>";
    h += "</div><div class=\"legend\"></div><div class=\"scale\"><span style=\"left:0\">FLIP 0 (no visible "
         "difference)</span><span style=\"left:20%\">0.2</span><span style=\"left:40%\">0.4</span><span "
         "style=\"left:60%\">0.6</span><span style=\"left:80%\">0.8</span><span style=\"left:100%\">1 (largest)</span></div>";
    h += metrics_rows(r);
    h += "<p>Regenerate the golden (accept the actual image): <code>" + markup_escape(cmd) + "</code></p></body></html>\n";
    write_text_file(dir / page_file(e.name), h);
}

}  // namespace

void write_html_report(const std::vector<FolderEntry>& entries, const FolderArgs& args, const DiffSettings&) {
    const fs::path dir(args.html);
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw InputError("cannot create HTML report directory '" + dir.string() + "': " + ec.message());
    std::string index = std::string("<!doctype html><html><head><meta charset=\"utf-8\"><title>sweeptrace diff</title>") +
                        style + "</head><body><h1>sweeptrace diff: " + markup_escape(args.actual) + " against " +
                        markup_escape(args.golden) + "</h1><table><tr><th>image</th><th>verdict</th><th>FLIP mean</th>"
                        "<th>golden</th><th>actual</th><th>heatmap</th></tr>";
    for (const FolderEntry& e : entries) {
        index += "<tr><td>" + markup_escape(e.name) + "</td><td class=\"" + e.status() + "\">" + e.status() + "</td>";
        if (!e.error.empty()) {
            index += "<td colspan=\"4\">" + markup_escape(e.error) + "</td></tr>";
            continue;
        }
        write_page(e, args, dir);
        index += "<td>" + number_text(e.report.flip.mean) + "</td>";
        for (const char* panel : {"golden", "actual", "heatmap"})
            index += "<td><a href=\"" + markup_escape(page_file(e.name)) + "\"><img src=\"" +
                     markup_escape(panel_file(e.name, panel)) + "\" width=\"160\" alt=\"" + panel + "\"></a></td>";
        index += "</tr>";
    }
    write_text_file(dir / "index.html", index + "</table></body></html>\n");
}

}  // namespace sweeptrace
