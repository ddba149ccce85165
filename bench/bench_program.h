// The shape both benchmark programs share: parse the options (CLI11 prints help and usage
// errors itself), run, and turn an error into one line and clrender's exit codes.
#pragma once

#include <exception>
#include <iostream>
#include <optional>

#include "core/errors.h"

namespace clr::bench {

// `parse(argc, argv, exit_code)` gives the options, or nothing with exit_code set; `run`
// takes them and returns the exit code.
template <typename Parse, typename Run>
int run_bench_program(const char* program, int argc, char** argv, Parse parse, Run run) {
    try {
        int exit_code = 0;
        auto options = parse(argc, argv, exit_code);
        return options ? run(*options) : exit_code;
    } catch (const Error& error) {
        std::cerr << program << ": error: " << error.what() << "\n";
        return error.code();
    } catch (const std::exception& error) {
        std::cerr << program << ": error: " << error.what() << "\n";
        return kExitDevice;
    }
}

}  // namespace clr::bench
