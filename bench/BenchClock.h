#pragma once
// The clocks the benchmarks report: process CPU time (all threads) and wall time, in seconds.

#include <ctime>

namespace bench {

/// CPU seconds of the whole process: the machine is shared, so wall time says more about the
/// neighbours.
inline double cpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// Seconds of a monotonic wall clock.
inline double wallSeconds() {
    timespec t{};
    clock_gettime(CLOCK_MONOTONIC, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace bench
