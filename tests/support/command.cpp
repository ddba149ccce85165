#include "support/command.h"

#include <sys/wait.h>

#include <array>
#include <cstdio>

namespace clr::testing {

namespace {

// The exit code and output of the shell command line `command`.
CommandResult run_command(const std::string& command) {
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

std::string in_folder(const std::string& folder) { return folder.empty() ? "" : "cd '" + folder + "' && "; }

}  // namespace

CommandResult run_clrender(const std::string& arguments, const std::string& folder, const std::string& environment) {
    return run_command(in_folder(folder) + environment + " '" + CLRENDER_BINARY + "' " + arguments + " 2>&1");
}

CommandResult run_clrender_interrupted(const std::string& arguments, const std::string& folder, double seconds) {
    // Standard error to the pipe, standard output dropped; the shell ends with clrender's code.
    return run_command(in_folder(folder) + "{ '" + CLRENDER_BINARY + "' " + arguments +
                       " 2>&1 >/dev/null & pid=$!; sleep " + std::to_string(seconds) +
                       "; kill -INT $pid; wait $pid; }");
}

std::string frame_name(int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "f_%04d.png", frame);
    return name;
}

}  // namespace clr::testing
