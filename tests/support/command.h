// Runs the clrender binary as a user would, capturing its exit code and output.
#pragma once

#include <string>

#include "support/temp_folder.h"  // TempFolder, which tests that run clrender use

namespace clr::testing {

struct CommandResult {
    int exit_code = -1;
    std::string output;  // stdout and stderr together
};

// Runs `clrender <arguments>` through the shell in `folder` (empty: the current one), with
// optional environment assignments placed before it ("CLRENDER_DEVICE=x").
CommandResult run_clrender(const std::string& arguments, const std::string& folder = "", const std::string& environment = "");

// Runs `clrender <arguments>` in `folder` as run_clrender() does, presses Ctrl-C (SIGINT) after
// `seconds` and waits for it: its exit code, and its standard error (standard output dropped).
CommandResult run_clrender_interrupted(const std::string& arguments, const std::string& folder, double seconds);

// The file of frame `frame` under the pattern the animation tests give clrender, "f_%04d.png".
std::string frame_name(int frame);

}  // namespace clr::testing
