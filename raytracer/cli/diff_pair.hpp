#pragma once
// One comparison of `sweeptrace diff`: every metric and the verdict, computed before anything is
// written, so an output problem can never hide or change the verdict. Used by the two-image mode
// and by the folder mode (one per matched name).
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "raytracer/image/diff.hpp"
#include "raytracer/image/flip.hpp"

namespace sweeptrace {

// Exit codes, documented in `diff --help` and README.md.
constexpr int diff_exit_pass = 0, diff_exit_fail = 1, diff_exit_bad_input = 2, diff_exit_warn = 4;

struct DiffSettings {
    DiffOptions metric_options;        // space and pixel threshold
    double max_rmse = 0.05;            // not applied when variances are given
    double max_share = 0.01;           // not applied when variances are given
    double max_abs = -1.0;             // hard limit on any channel difference; < 0: off
    double max_delta_e = -1.0;         // simplified blurred CIELAB; < 0: off
    double max_flip = 0.04;            // mean FLIP
    bool max_flip_given = false;       // with variances, FLIP limits apply only when asked for
    double warn_flip = 0.03;           // mean FLIP over this (and within the limits): warning
    double max_local_flip = 0.3;       // mean FLIP over the worst 3 x 3 pixels
    double max_alpha = 0.05;           // largest accepted |alpha_A - alpha_B|
    glm::vec3 background{0.0f};        // linear colour composited under images with alpha
    FlipOptions flip;                  // ppd, tone mapper, exposures; .hdr decided per pair
    std::string flip_mode = "auto";    // auto (HDR when both inputs are .exr/.pfm), ldr, hdr
    double false_alarm = 0.01;         // family-wise rate of the noise test
    int block = 8;                     // noise test block size
};

struct PairInputs {
    std::string a, b;                    // B is the reference
    std::string variance_a, variance_b;  // both or neither: the noise test
};

struct PairReport {
    PairInputs inputs;
    DiffMetrics metrics;
    FlipResult flip;
    double flip_local = 0.0;
    bool alpha_present = false;
    double alpha_max_difference = 0.0;
    std::optional<BlockTestResult> noise;
    std::vector<std::string> failures, warnings;
    int exit_code() const;
    const char* status() const;  // "pass", "WARN", "FAIL"
};

// Throws InputError on unreadable or mismatched inputs (naming them).
PairReport compare_pair(const PairInputs& inputs, const DiffSettings& settings);

// The full report, numbers at full precision (%.9g), verdict last.
void print_report(const PairReport& report, std::FILE* out);

// Shortest round-trip-safe text for a number: "%.9g", "inf", "nan".
std::string number_text(double value);

}  // namespace sweeptrace
