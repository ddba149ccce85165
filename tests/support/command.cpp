#include "support/command.h"

#include <sys/wait.h>

#include <array>
#include <cstdio>

namespace clr::testing {

CommandResult run_clrender(const std::string& arguments, const std::string& folder, const std::string& environment) {
    std::string command = (folder.empty() ? "" : "cd '" + folder + "' && ") + environment + " '" + CLRENDER_BINARY +
                          "' " + arguments + " 2>&1";
    CommandResult result;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return result;
    std::array<char, 4096> buffer;
    std::size_t count;
    while ((count = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), count);
    int status = pclose(pipe);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

std::string frame_name(int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "f_%04d.png", frame);
    return name;
}

}  // namespace clr::testing
