#include "support/address_space_child.h"

#include <malloc.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>

namespace clr::testing {
namespace {

// Limits the address space to what the process holds now plus `spare` bytes; false where that
// cannot be done.
bool limit_address_space(std::uint64_t spare) {
    // Memory that earlier tests of this process freed, but the allocator kept, would be room
    // beyond `spare`: given back first.
    ::malloc_trim(0);
    long pages = 0;  // the address space the process holds now, from /proc/self/statm
    std::FILE* statm = std::fopen("/proc/self/statm", "r");
    const bool measured = statm && std::fscanf(statm, "%ld", &pages) == 1;
    if (statm) std::fclose(statm);
    const rlim_t limit = static_cast<rlim_t>(pages) * ::sysconf(_SC_PAGESIZE) + spare;
    rlimit bounded{limit, limit};
    return measured && ::setrlimit(RLIMIT_AS, &bounded) == 0;
}

}  // namespace

bool passes_in_bounded_child(const ChildBounds& bounds, const std::function<bool()>& check) {
    const pid_t child = ::fork();
    if (child == 0) {
        if (bounds.seconds > 0) ::alarm(bounds.seconds);
        bool passed = false;
        if (!bounds.address_space_to_spare || limit_address_space(*bounds.address_space_to_spare)) {
            try {
                passed = check();
            } catch (...) {
            }
        }
        ::_exit(passed ? 0 : 1);
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace clr::testing
