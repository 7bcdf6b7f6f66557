// Accuracy checks for anyone's intersector (issue #14 part 5): the exported ray families scored
// back from a results file reproduce the built-in table, and the C++ hook measures a routine.
#include <catch2/catch.hpp>

#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "collision/intersect.hpp"
#include "image_test_support.hpp"

using sweeptrace::testing::read_file_text;
using sweeptrace::testing::run_sweeptrace;
using sweeptrace::testing::ScratchDir;
using Catch::Matchers::Contains;
using nlohmann::json;

namespace {

glm::vec3 vec(const json& j) { return {j[0].get<float>(), j[1].get<float>(), j[2].get<float>()}; }

collision::Ray ray_of(const json& j) {
    collision::Ray r;
    r.origin = vec(j["origin"]);
    r.dir = vec(j["dir"]);
    r.tmin = j["tmin"].get<float>();
    r.tmax = j["tmax"].is_null() ? std::numeric_limits<float>::infinity() : j["tmax"].get<float>();
    return r;
}

// What someone else's program does with the export: read each case, intersect, write a result.
void answer(const std::filesystem::path& cases, std::ofstream& results, bool box) {
    std::ifstream in(cases);
    std::string line;
    while (std::getline(in, line)) {
        const json c = json::parse(line);
        collision::RayHit h;
        bool hit = false;
        if (box) hit = collision::intersect(ray_of(c["ray"]), collision::Aabb{vec(c["shape"]["center"]), vec(c["shape"]["size"])}, h);
        else hit = collision::intersect(ray_of(c["ray"]), collision::Sphere{vec(c["shape"]["center"]), c["shape"]["radius"].get<float>()}, h);
        json r{{"case", c["case"]}, {"hit", hit}};
        if (hit) r["t"] = h.t;
        results << r.dump() << '\n';
    }
}

// CSV rows keyed by shape/variant/family, the Mrays/s column dropped (timing differs).
std::map<std::string, std::string> csv_rows(const std::string& text, const std::string& variant) {
    std::map<std::string, std::string> rows;
    std::istringstream in(text);
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
        std::vector<std::string> cells;
        std::stringstream cs(line);
        for (std::string cell; std::getline(cs, cell, ',');) cells.push_back(cell);
        if (cells.size() < 4 || cells[1] != variant) continue;
        std::string rest;
        for (std::size_t i = 3; i + 1 < cells.size(); ++i) rest += cells[i] + ",";
        rows[cells[0] + "/" + cells[2]] = rest;
    }
    return rows;
}

}  // namespace

TEST_CASE("accuracy --export-rays / --score reproduce the built-in table for the robust routine", "[accuracy][cli]") {
    ScratchDir dir("accuracy-exchange");
    const std::string rays = " --rays 300 --seed 5";
    REQUIRE(run_sweeptrace("accuracy --export-rays " + (dir / "rays").string() + " --shape sphere --shape box" + rays,
                           dir.path()).exit_code == 0);
    const json manifest = json::parse(read_file_text(dir / "rays" / "manifest.json"));
    CHECK(manifest["rays_per_family"] == 300);
    std::ofstream results(dir / "results.jsonl");
    std::size_t files = 0;
    for (const json& f : manifest["files"]) {
        answer(dir / "rays" / f["file"].get<std::string>(), results, f["shape"] == "box");
        ++files;
    }
    results.close();
    CHECK(files == 12);  // sphere: 5 families, box: 7 (the surface families need the routine's own hits)

    const auto scored = run_sweeptrace("accuracy --score " + (dir / "results.jsonl").string() + rays + " --csv " +
                                           (dir / "scored.csv").string(), dir.path());
    REQUIRE(scored.exit_code == 0);
    CHECK_THAT(scored.output, Contains("| sphere | results | grazing |") && Contains("Columns:"));
    REQUIRE(run_sweeptrace("accuracy --shape sphere --shape box" + rays + " --csv " + (dir / "builtin.csv").string(),
                           dir.path()).exit_code == 0);
    const auto mine = csv_rows(read_file_text(dir / "scored.csv"), "results");
    const auto builtin = csv_rows(read_file_text(dir / "builtin.csv"), "robust");
    REQUIRE(mine.size() == files);
    for (const auto& [key, row] : mine) {
        INFO(key);
        REQUIRE(builtin.count(key) == 1);
        CHECK(row == builtin.at(key));
    }
}

TEST_CASE("accuracy --score names the file and line of a bad result, and refuses partial families", "[accuracy][cli]") {
    ScratchDir dir("accuracy-score-bad");
    sweeptrace::testing::write_file_text(dir / "bad.jsonl", "{\"case\": \"sphere/uniform/0\", \"hit\": true, \"t\": 1}\nnot json\n");
    const auto bad = run_sweeptrace("accuracy --score " + (dir / "bad.jsonl").string(), dir.path());
    CHECK(bad.exit_code == 2);
    CHECK_THAT(bad.output, Contains("bad.jsonl:2"));
    sweeptrace::testing::write_file_text(dir / "few.jsonl", "{\"case\": \"sphere/uniform/0\", \"hit\": false}\n");
    const auto few = run_sweeptrace("accuracy --score " + (dir / "few.jsonl").string() + " --rays 10", dir.path());
    CHECK(few.exit_code == 2);
    CHECK_THAT(few.output, Contains("1 results for 10 cases"));
}

TEST_CASE("the C++ hook measures a registered routine on every family, secondary rays included", "[accuracy]") {
    ScratchDir dir("accuracy-hook");
    const std::string command = std::string("\"") + SWEEPTRACE_BINARY_DIR + "/examples/custom_intersector\" 400 >" +
                                (dir / "out.txt").string() + " 2>&1";
    REQUIRE(std::system(command.c_str()) == 0);
    const std::string out = read_file_text(dir / "out.txt");
    CHECK_THAT(out, Contains("| sphere | textbook | uniform | 400 |") && Contains("| sphere | textbook | surface-out |") &&
                        Contains("| sphere | textbook | surface-in |") && Contains("| sphere | robust | uniform |"));
}

TEST_CASE("accuracy --score: optional hit points are scored relative to the distance travelled", "[accuracy][cli]") {
    ScratchDir dir("accuracy-points");
    REQUIRE(run_sweeptrace("accuracy --export-rays " + (dir / "rays").string() + " --shape sphere --rays 200", dir.path())
                .exit_code == 0);
    // Answer with the reference itself, but every point 1 % further along the ray than t_ref:
    // the point error is 0.01 on every hit (to float rounding of the written point).
    std::ifstream in(dir / "rays" / "sphere-uniform.jsonl");
    std::ofstream out(dir / "results.jsonl");
    std::string line;
    while (std::getline(in, line)) {
        const json c = json::parse(line);
        const bool hit = c["reference"]["outcome"] == "hit";
        json r{{"case", c["case"]}, {"hit", hit}};
        if (hit) {
            const double t = c["reference"]["t"];
            const collision::Ray ray = ray_of(c["ray"]);
            r["t"] = t;
            r["point"] = json::array({ray.origin.x + 1.01 * t * ray.dir.x, ray.origin.y + 1.01 * t * ray.dir.y,
                                      ray.origin.z + 1.01 * t * ray.dir.z});
        }
        out << r.dump() << '\n';
    }
    out.close();
    const auto r = run_sweeptrace("accuracy --score " + (dir / "results.jsonl").string() + " --rays 200", dir.path());
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.output, Contains("| sphere | results | uniform | 200 | 0 | 0 | 0 (0%) | 0 |"));
    CHECK_THAT(r.output, Contains("| sphere | uniform | 200 | 0.01 | 0.01 | 0.01 |"));
}
