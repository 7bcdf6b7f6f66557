#include "raytracer/cli/interrupt.hpp"

#include <csignal>

#include "raytracer/image/atomic_file.hpp"

namespace sweeptrace {

namespace {

// Lock-free, so setting them from a signal handler is well defined.
std::atomic<bool> g_interrupted{false};
std::atomic<int> g_signal{0};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free);

extern "C" void on_stop_signal(int sig) {
    int none = 0;
    if (g_signal.compare_exchange_strong(none, sig)) {
        g_interrupted.store(true);
        return;
    }
    // The second signal: nothing more will be written, so no temporary file may stay behind.
    remove_temporaries_in_progress();
    std::signal(sig, SIG_DFL);
    std::raise(sig);
}

}  // namespace

InterruptGuard::InterruptGuard() {
    g_interrupted.store(false);
    g_signal.store(0);
    previous_int_ = std::signal(SIGINT, on_stop_signal);
    previous_term_ = std::signal(SIGTERM, on_stop_signal);
}

InterruptGuard::~InterruptGuard() {
    std::signal(SIGINT, previous_int_ == SIG_ERR ? SIG_DFL : previous_int_);
    std::signal(SIGTERM, previous_term_ == SIG_ERR ? SIG_DFL : previous_term_);
}

const std::atomic<bool>* InterruptGuard::flag() { return &g_interrupted; }

int InterruptGuard::exit_code() {
    const int sig = g_signal.load();
    return 128 + (sig != 0 ? sig : SIGINT);
}

}  // namespace sweeptrace
