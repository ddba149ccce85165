// A render that another clrender started for itself (the viewer's video) stops when that
// clrender ends, however it ends. The viewer stops its video itself when it is stopped; killed
// outright (SIGKILL, the OOM killer) it can do nothing, and its video's render, in a process
// group of its own, rendered on to the end, using the CPUs, for nobody.
#pragma once

#include <sys/types.h>

#include <string>

namespace clr {

// The variable through which the starting clrender gives its process id: "PID".
inline constexpr const char* kStopWithParentVariable = "CLRENDER_STOP_WITH_PARENT";

// "CLRENDER_STOP_WITH_PARENT=PID" for this process, for the environment of a render it starts.
std::string stop_with_parent_entry();

// Where kStopWithParentVariable names this process's parent, asks the system for a signal when
// the parent's thread that started this process ends (PR_SET_PDEATHSIG), which becomes one
// SIGTERM to this process, answered as any SIGTERM: its unfinished files removed, exit 143. A
// parent gone already (it ended before this process asked) is the same SIGTERM at once. Nothing
// where the variable is unset or does not hold a process id. Called first thing in main().
void stop_with_parent_from_environment();

}  // namespace clr
