#pragma once
// Ctrl-C (SIGINT) and SIGTERM stop a render the same way: the first asks it to stop after the
// passes finished so far, which are written, and the process exits 128 + the signal number
// (130 for SIGINT, 143 for SIGTERM, as a shell reports a death by that signal). A second signal
// of either kind removes the temporary file of any write in progress (image/atomic_file.hpp) and
// kills the process by that signal at once.
#include <atomic>

namespace sweeptrace {

// Installs the handlers for its lifetime; one at a time.
class InterruptGuard {
public:
    InterruptGuard();
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

    // Set by the first signal; the renderer polls it.
    static const std::atomic<bool>* flag();
    // The exit code for an interrupted run: 128 + the first signal (130 if none was seen).
    static int exit_code();

private:
    void (*previous_int_)(int);
    void (*previous_term_)(int);
};

}  // namespace sweeptrace
