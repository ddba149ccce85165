#include "device/driver_settings.h"

#include <cstdlib>
#include <string>

namespace clr {

void apply_driver_settings() {
    // PoCL compiles a kernel's work-group function at its first enqueue, specialised for the
    // local size, a zero global offset and the grid's size, and compiles it again, generic,
    // when asked for the program's binary (which the program cache stores). Specialisation
    // off, the first enqueue uses the generic function that the binary needs anyway: one
    // compile of render_packets on a cold start instead of two, and the same pixels. Its
    // work-items each render a 16x16 tile, so the generic function's loop costs nothing
    // measurable (docs/benchmarks.md, Start-up).
    setenv("POCL_WORK_GROUP_SPECIALIZATION", "0", /*overwrite=*/0);
    // CLRENDER_CACHE_DIR=off promises no cache across runs; PoCL keeps one of its own (the
    // compiled kernels, under ~/.cache/pocl), which it then must not keep either
    // (docs/command-line.md, Options).
    if (const char* cache = std::getenv("CLRENDER_CACHE_DIR"); cache && (std::string(cache) == "off" || !*cache))
        setenv("POCL_KERNEL_CACHE", "0", /*overwrite=*/0);
}

void limit_cpu_threads(int threads) {
    const std::string count = std::to_string(threads);
    // The user's -t wins over the environment: it is the more specific request.
    setenv("POCL_MAX_PTHREAD_COUNT", count.c_str(), /*overwrite=*/1);
    setenv("POCL_CPU_MAX_CU_NUM", count.c_str(), /*overwrite=*/1);
}

}  // namespace clr
