#include "support/shell.h"

#include <sys/wait.h>

#include <array>
#include <cstdio>

namespace clr::testing {

CommandResult run_shell(const std::string& command) {
    CommandResult result;
    const std::string joined = "( " + command + " ) 2>&1";
    FILE* pipe = popen(joined.c_str(), "r");
    if (!pipe) return result;
    std::array<char, 4096> buffer;
    std::size_t count;
    while ((count = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), count);
    const int status = pclose(pipe);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

std::string shell_quoted(const std::string& text) {
    std::string quoted = "'";
    for (char c : text) {
        if (c == '\'')
            quoted += "'\\''";
        else
            quoted += c;
    }
    return quoted + "'";
}

}  // namespace clr::testing
