#pragma once
// The sweeptrace binary run as a user runs it, in a folder: its exit code and its stderr (left in
// the folder as stderr.txt), for the command-line tests.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace sweeptrace::test {

struct CliRun {
    int exit_code = -1;
    std::string err;
};

inline CliRun run_sweeptrace(const std::filesystem::path& dir, const std::string& args) {
    const std::filesystem::path binary = std::filesystem::path(SWEEPTRACE_BINARY_DIR) / "sweeptrace";
    const std::filesystem::path err = dir / "stderr.txt";
    const std::string cmd = "cd '" + dir.string() + "' && '" + binary.string() + "' " + args + " 2> stderr.txt > /dev/null";
    const int status = std::system(cmd.c_str());
    CliRun r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream in(err);
    r.err.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return r;
}

}  // namespace sweeptrace::test
