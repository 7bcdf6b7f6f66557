#pragma once
// Single-thread throughput is measured in the calling thread's CPU time, not wall time: the
// figures then do not depend on what else the machine runs (builds, other benchmarks), only
// on the code and the caches. Build times of multi-threaded builders (Embree) use wall time.
#include <time.h>

#include <chrono>

namespace sweeptrace::accuracy {

inline double thread_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// CPU time of every thread of the process: renders run on all cores, and this figure, unlike
// wall time, does not grow when other processes share the machine.
inline double process_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

inline double wall_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace sweeptrace::accuracy
