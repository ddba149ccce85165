// clrender's only entry point: parse the command line, run, and turn every error into one
// message and the documented exit code (docs/command-line.md, Exit codes).
#include <exception>
#include <functional>
#include <iostream>
#include <string_view>

#include "app/compare_command.h"
#include "app/compare_options.h"
#include "app/exit_status.h"
#include "app/options.h"
#include "app/run.h"
#include "view/view_command.h"

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
    // `clrender view SCENE`: the live viewer, with options of its own (a scene file named
    // "view" is still rendered as ./view).
    if (argc > 1 && std::string_view(argv[1]) == "view") return clr::view_main(argc - 1, argv + 1);
    if (clr::is_compare_command(argc, argv)) {  // clrender compare SCENE IMAGE
        clr::ParsedCompare parsed = clr::parse_compare_options(argc - 1, argv + 1);
        if (parsed.exit_code) return *parsed.exit_code;
        return exit_code_of([&] { return clr::run_compare(parsed.request); });
    }
    clr::ParsedOptions parsed = clr::parse_options(argc, argv);
    if (parsed.exit_code) return *parsed.exit_code;
    return exit_code_of([&] { return clr::run(parsed.options); });
}
