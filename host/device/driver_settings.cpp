#include "device/driver_settings.h"

#include <cstdlib>

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
}

}  // namespace clr
