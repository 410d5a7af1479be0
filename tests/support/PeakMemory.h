#pragma once
// Peak memory of a piece of work: Linux resets a process's peak resident set (VmHWM) to its
// current size when "5" is written to /proc/self/clear_refs, so the peak after the work, less
// the resident size before it, is what the work itself needed at most.

#include <catch2/catch.hpp>

#include <chrono>
#include <cstddef>
#include <fstream>
#include <functional>
#include <string>

namespace test_support {

/// VmHWM or VmRSS of this process in bytes (0 when /proc does not say).
inline std::size_t procStatusBytes(const std::string& key) {
    std::ifstream status("/proc/self/status");
    std::string word;
    while (status >> word)
        if (word == key + ":") {
            std::size_t kib = 0;
            status >> kib;
            return kib * 1024;
        }
    return 0;
}

/// What one run of `work` cost: its wall time and its peak resident memory above the start.
struct WorkCost {
    double seconds = 0;
    std::size_t peakBytes = 0;
    bool peakMeasured = false;  ///< false where the peak could not be reset (then peakBytes is 0)
};

inline WorkCost measureWork(const std::function<void()>& work) {
    WorkCost cost;
    std::ofstream reset("/proc/self/clear_refs");
    cost.peakMeasured = static_cast<bool>(reset << "5" << std::flush);
    reset.close();
    const std::size_t before = procStatusBytes("VmRSS");
    const auto t0 = std::chrono::steady_clock::now();
    work();
    cost.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const std::size_t peak = procStatusBytes("VmHWM");
    if (cost.peakMeasured) cost.peakBytes = peak > before ? peak - before : 0;
    return cost;
}

/// Runs `read`, which must refuse its input by throwing `Refusal`, and returns the message; checks
/// that the refusal came quickly (under a second) and small (under 256 MB of peak memory).
template <class Refusal>
std::string cheapRefusal(const std::function<void()>& read) {
    std::string message;
    const WorkCost cost = measureWork([&] {
        try {
            read();
        } catch (const Refusal& e) {
            message = e.what();
        }
    });
    CHECK(cost.seconds < 1.0);
    REQUIRE(cost.peakMeasured);
    CHECK(cost.peakBytes < (256u << 20));
    return message;
}

}  // namespace test_support
