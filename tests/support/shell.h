// Runs a shell command line as a test's helper program (cmake, bash, man), capturing its exit
// code and output.
#pragma once

#include <string>

#include "support/command.h"  // CommandResult

namespace clr::testing {

// `sh -c command` with standard error joined to standard output.
CommandResult run_shell(const std::string& command);

// `text` quoted for the shell, whatever it contains.
std::string shell_quoted(const std::string& text);

}  // namespace clr::testing
