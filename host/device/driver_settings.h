// Settings that clrender gives OpenCL drivers through their environment variables, which the
// drivers read once, when they are loaded (docs/benchmarks.md, Start-up).
#pragma once

namespace clr {

// Sets each variable that the user has not set. Runs before main() (device_selection.cpp):
// changing the environment is safe only while no other thread may read it.
void apply_driver_settings();

// -t N: PoCL's CPU device runs its work-groups on this many threads, its compute units
// (POCL_MAX_PTHREAD_COUNT in PoCL 3, POCL_CPU_MAX_CU_NUM from PoCL 4 on). Must run before the
// platform loads, i.e. before list_devices(), while no other thread runs. Other drivers ignore
// these variables: select_compute_units() then makes a sub-device of that size.
void limit_cpu_threads(int threads);

}  // namespace clr
