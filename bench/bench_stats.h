// Small timing helpers shared by both sides of the benchmark.
#pragma once

#include <algorithm>
#include <vector>

namespace clr::bench {

// The median of a non-empty sample (the mean of the middle two for an even count). The
// median rather than the mean, because a frame that another process interrupted should not
// move the figure.
inline double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    std::size_t mid = values.size() / 2;
    return values.size() % 2 ? values[mid] : (values[mid - 1] + values[mid]) / 2;
}

// Primary rays per second, in millions: one ray per pixel.
inline double mrays_per_s(int width, int height, double ms) {
    return ms > 0 ? static_cast<double>(width) * height / (ms * 1e3) : 0;
}

// A warm-up frame slower than this counts as the only timed frame: first-use costs are
// small next to it, and repeating it would take minutes (brute-force kernels on the big
// scenes). Keeps a whole run within about two minutes on a 2-core machine.
constexpr double kSlowFrameMs = 2000;

}  // namespace clr::bench
