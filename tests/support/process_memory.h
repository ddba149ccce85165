// The memory a process holds, as /proc tells it, for tests that check what a request or a
// scene costs a running clrender (a viewer) in memory.
#pragma once

#include <sys/types.h>

#include <functional>

namespace clr::testing {

// The resident memory of process `pid`, in MiB (0 once it is gone).
long resident_mib(pid_t pid);

// How far above its resident memory before `work` process `pid` rose while `work` ran, in MiB
// (looked at every 5 ms).
long rise_during(pid_t pid, const std::function<void()>& work);

}  // namespace clr::testing
