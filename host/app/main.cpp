// clrender's only entry point: parse the command line, run, and turn every error into one
// message and the documented exit code (docs/command-line.md, Exit codes).
#include <exception>
#include <iostream>
#include <string_view>

#include "app/exit_status.h"
#include "app/options.h"
#include "app/run.h"
#include "view/view_command.h"

int main(int argc, char** argv) {
    // `clrender view SCENE`: the live viewer, with options of its own (a scene file named
    // "view" is still rendered as ./view).
    if (argc > 1 && std::string_view(argv[1]) == "view") return clr::view_main(argc - 1, argv + 1);
    clr::ParsedOptions parsed = clr::parse_options(argc, argv);
    if (parsed.exit_code) return *parsed.exit_code;
    try {
        return clr::run(parsed.options);
    } catch (...) {
        const clr::ExitStatus status = clr::exit_status_for(std::current_exception());
        std::cerr << status.message << "\n";
        return status.code;
    }
}
