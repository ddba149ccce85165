// The CPUs the test process may run on, for tests that pin a child (taskset) or a thread of
// their own to one.
#pragma once

namespace clr::testing {

// The first CPU this process may run on (0 when the affinity cannot be read).
int first_usable_cpu();

}  // namespace clr::testing
