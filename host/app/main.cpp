// clrender's only entry point: parse the command line, run, and turn every error into one
// message and the documented exit code (docs/command-line.md, Exit codes).
#include <exception>
#include <functional>
#include <iostream>
#include <string>
#include <string_view>

#include "app/compare_command.h"
#include "app/compare_options.h"
#include "app/exit_status.h"
#include "app/options.h"
#include "app/run.h"
#include "app/standard_output.h"
#include "core/errors.h"
#include "core/message_lines.h"
#include "core/stop_with_parent.h"
#include "view/view_command.h"

namespace {

// A run that succeeded but whose standard output did not all arrive (a full disk, a closed
// pipe) failed: exit 4 with one line, never 0.
int checked_standard_output(int code) {
    const std::string problem = clr::flush_standard_output();
    if (code != clr::kExitOk || problem.empty()) return code;
    std::cerr << clr::message_line("error", "standard output: cannot write what was asked for (" + problem + ")", clr::kExitOutput);
    return clr::kExitOutput;
}

// --progress json makes every line on standard error JSON, the parser's errors too: looked
// for before the parser runs.
bool asks_for_json_progress(int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument == "--progress=json" || (argument == "--progress" && i + 1 < argc && std::string(argv[i + 1]) == "json"))
            return true;
    }
    return false;
}

// The exit code of `command`, or of the exception that ended it, after its one message; a
// command whose standard output did not all arrive failed.
int exit_code_of(const std::function<int()>& command) {
    try {
        return checked_standard_output(command());
    } catch (...) {
        const clr::ExitStatus status = clr::exit_status_for(std::current_exception());
        std::cerr << clr::message_line("error", status.problem, status.code);
        return status.code;
    }
}

}  // namespace

int main(int argc, char** argv) {
    // A video render the viewer started ends with the viewer, however the viewer ends.
    clr::stop_with_parent_from_environment();
    // `clrender view SCENE`: the live viewer, with options of its own (a scene file named
    // "view" is still rendered as ./view).
    if (argc > 1 && std::string_view(argv[1]) == "view") return clr::view_main(argc - 1, argv + 1);
    if (clr::is_compare_command(argc, argv)) {  // clrender compare SCENE IMAGE
        clr::ParsedCompare parsed = clr::parse_compare_options(argc - 1, argv + 1);
        if (parsed.exit_code) return checked_standard_output(*parsed.exit_code);
        return exit_code_of([&] { return clr::run_compare(parsed.request); });
    }
    clr::set_json_messages(asks_for_json_progress(argc, argv));
    clr::ParsedOptions parsed = clr::parse_options(argc, argv);
    if (parsed.exit_code) return checked_standard_output(*parsed.exit_code);  // --help, --version
    return exit_code_of([&] { return clr::run(parsed.options); });
}
