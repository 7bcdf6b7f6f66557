#pragma once
// Each subcommand registers itself on the app; its callback stores the process exit code.
#include <CLI/CLI.hpp>

namespace sweeptrace {

void add_render_command(CLI::App& app, int& exit_code);
void add_diff_command(CLI::App& app, int& exit_code);
void add_accuracy_command(CLI::App& app, int& exit_code);
void add_bench_command(CLI::App& app, int& exit_code);
void add_noise_bench_command(CLI::App& app, int& exit_code);
void add_merge_command(CLI::App& app, int& exit_code);
void add_convert_command(CLI::App& app, int& exit_code);
void add_reference_check_command(CLI::App& app, int& exit_code);
void add_denoise_command(CLI::App& app, int& exit_code);

}  // namespace sweeptrace
