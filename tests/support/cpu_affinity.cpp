#include "support/cpu_affinity.h"

#include <sched.h>

namespace clr::testing {

int first_usable_cpu() {
    cpu_set_t allowed;
    if (::sched_getaffinity(0, sizeof(allowed), &allowed) != 0) return 0;
    int cpu = 0;
    while (cpu < CPU_SETSIZE && !CPU_ISSET(cpu, &allowed)) ++cpu;
    return cpu;
}

}  // namespace clr::testing
