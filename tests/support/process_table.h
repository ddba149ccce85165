// The system's processes as /proc lists them, for tests that look for what a clrender started:
// an encoder's process group, a viewer's video render.
#pragma once

#include <sys/types.h>

#include <vector>

namespace clr::testing {

struct ProcessEntry {
    pid_t pid = 0;
    char state = 0;  // 'Z': a zombie, ended, only waiting for its parent to collect its status
    pid_t parent = 0;
    pid_t group = 0;  // its process group
};

// Every process that /proc lists now (those that end while it is read may be missing).
std::vector<ProcessEntry> process_table();

// Whether process `pid` is in `table` and has not ended (a zombie has).
bool still_runs(const std::vector<ProcessEntry>& table, pid_t pid);

}  // namespace clr::testing
