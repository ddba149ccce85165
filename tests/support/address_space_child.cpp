#include "support/address_space_child.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>

namespace clr::testing {

bool passes_with_address_space_to_spare(std::uint64_t spare, const std::function<bool()>& check) {
    const pid_t child = ::fork();
    if (child == 0) {
        long pages = 0;  // the address space the child holds now, from /proc/self/statm
        std::FILE* statm = std::fopen("/proc/self/statm", "r");
        const bool measured = statm && std::fscanf(statm, "%ld", &pages) == 1;
        if (statm) std::fclose(statm);
        const rlim_t limit = static_cast<rlim_t>(pages) * ::sysconf(_SC_PAGESIZE) + spare;
        rlimit bounded{limit, limit};
        bool passed = false;
        if (measured && ::setrlimit(RLIMIT_AS, &bounded) == 0) {
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
