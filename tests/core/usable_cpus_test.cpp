// usable_cpu_count() counts the CPUs the process may run on (its affinity), not the machine's.
#include "core/usable_cpus.h"

#include <gtest/gtest.h>
#include <sched.h>

namespace clr {
namespace {

TEST(UsableCpus, FollowsTheAffinityMask) {
    cpu_set_t original;
    ASSERT_EQ(::sched_getaffinity(0, sizeof(original), &original), 0);
    EXPECT_EQ(usable_cpu_count(), CPU_COUNT(&original));

    // One CPU allowed (on any machine): as `taskset -c N` or a one-CPU Slurm task would.
    int first = 0;
    while (!CPU_ISSET(first, &original)) ++first;
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(first, &one);
    ASSERT_EQ(::sched_setaffinity(0, sizeof(one), &one), 0);
    const int counted = usable_cpu_count();
    ASSERT_EQ(::sched_setaffinity(0, sizeof(original), &original), 0);
    EXPECT_EQ(counted, 1);
}

}  // namespace
}  // namespace clr
