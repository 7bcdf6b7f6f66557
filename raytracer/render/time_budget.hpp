#pragma once
// The clock a render's time budget (RenderOptions::time_budget) is counted on. Wall time is what
// a user waiting for an image means; the process's CPU time (every thread) is what equal-time
// comparisons on a shared machine need, since it does not grow while other processes run.
#include <time.h>

#include <algorithm>
#include <chrono>

namespace sweeptrace {

enum class BudgetClock { Wall, ProcessCpu };

class TimeBudget {
public:
    TimeBudget(BudgetClock clock, double seconds) : clock_(clock), seconds_(seconds), start_(now()) {}

    double elapsed() const { return now() - start_; }
    bool limited() const { return seconds_ > 0.0; }
    bool spent() const { return limited() && elapsed() >= seconds_; }
    double left() const { return limited() ? std::max(0.0, seconds_ - elapsed()) : -1.0; }
    double fraction() const { return limited() ? std::min(1.0, elapsed() / seconds_) : 0.0; }

private:
    double now() const {
        if (clock_ == BudgetClock::Wall)
            return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
        timespec ts{};
        clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
        return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
    }

    BudgetClock clock_;
    double seconds_;
    double start_;
};

}  // namespace sweeptrace
