// How many CPUs this process may run on: its affinity mask (taskset, a Slurm task's cpuset),
// not the machine's count, which can be far larger.
#pragma once

namespace clr {

// At least 1.
int usable_cpu_count();

}  // namespace clr
