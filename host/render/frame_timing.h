// How long one frame took, for --stats and the benchmarks.
#pragma once

namespace clr {

struct FrameTiming {
    double kernel_ms = 0;  // device time of the render kernel (OpenCL profiling events)
    double total_ms = 0;   // wall time from enqueue to the finished image in host memory
};

}  // namespace clr
