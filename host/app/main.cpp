// clrender's only entry point: parse the command line, run, and turn every error into one
// message and the documented exit code (docs/command-line.md, Exit codes).
#include <exception>
#include <functional>
#include <iostream>

#include "app/compare_command.h"
#include "app/compare_options.h"
#include "app/exit_status.h"
#include "app/options.h"
#include "app/run.h"

namespace {

// The exit code of `command`, or of the exception that ended it, after its one message.
int exit_code_of(const std::function<int()>& command) {
    try {
        return command();
    } catch (...) {
        const clr::ExitStatus status = clr::exit_status_for(std::current_exception());
        std::cerr << status.message << "\n";
        return status.code;
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (clr::is_compare_command(argc, argv)) {  // clrender compare SCENE IMAGE
        clr::ParsedCompare parsed = clr::parse_compare_options(argc - 1, argv + 1);
        if (parsed.exit_code) return *parsed.exit_code;
        return exit_code_of([&] { return clr::run_compare(parsed.request); });
    }
    clr::ParsedOptions parsed = clr::parse_options(argc, argv);
    if (parsed.exit_code) return *parsed.exit_code;
    return exit_code_of([&] { return clr::run(parsed.options); });
}
