// Settings that clrender gives OpenCL drivers through their environment variables, which the
// drivers read once, when they are loaded (docs/benchmarks.md, Start-up).
#pragma once

namespace clr {

// Sets each variable that the user has not set. Runs before main() (device_selection.cpp):
// changing the environment is safe only while no other thread may read it.
void apply_driver_settings();

}  // namespace clr
