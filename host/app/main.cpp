// clrender's only entry point: parse the command line, run, and turn every error into one
// message and the documented exit code (docs/command-line.md, Exit codes).
#include <exception>
#include <iostream>

#include "app/exit_status.h"
#include "app/options.h"
#include "app/run.h"

int main(int argc, char** argv) {
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
