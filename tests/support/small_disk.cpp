#include "support/small_disk.h"

#include <sys/wait.h>

#include <cstdlib>

namespace clr::testing {

bool can_mount_small_disks() {
    static const bool can = std::system("unshare -rm sh -c 'mount -t tmpfs -o size=16k tmpfs /mnt' >/dev/null 2>&1") == 0;
    return can;
}

int run_in_mount_namespace(const std::string& folder, const std::string& script) {
    const std::string command = "cd '" + folder + "' && CLRENDER='" + CLRENDER_BINARY +
                                "' timeout 120 unshare -rm sh -ec '" + script + "'";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool have_program(const std::string& program) {
    return std::system(("command -v '" + program + "' >/dev/null 2>&1").c_str()) == 0;
}

}  // namespace clr::testing
