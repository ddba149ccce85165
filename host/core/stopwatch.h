// Time since a moment, on the steady clock (never set back), for the timings clrender reports
// (--stats, progress, the benchmarks): one definition, so that every figure is taken alike.
#pragma once

#include <chrono>

namespace clr {

class Stopwatch {
public:
    using Clock = std::chrono::steady_clock;

    Stopwatch() : start_(Clock::now()) {}

    double elapsed_ms() const { return std::chrono::duration<double, std::milli>(Clock::now() - start_).count(); }
    double elapsed_seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

private:
    Clock::time_point start_;
};

}  // namespace clr
