// clrender's only entry point: parse the command line, run, and turn every error into one
// message and the documented exit code (docs/command-line.md, Exit codes).
#include <exception>
#include <iostream>
#include <new>

#include "app/options.h"
#include "app/run.h"
#include "core/errors.h"
#include "core/printable_text.h"

int main(int argc, char** argv) {
    clr::ParsedOptions parsed = clr::parse_options(argc, argv);
    if (parsed.exit_code) return *parsed.exit_code;
    try {
        return clr::run(parsed.options);
    } catch (const clr::Error& error) {
        // One line whatever the message quotes (a file name with a newline, an encoder's log).
        std::cerr << "clrender: error: " << clr::printable(error.what()) << "\n";
        return error.code();
    } catch (const std::bad_alloc&) {
        std::cerr << "clrender: error: out of memory\n";
        return clr::kExitDevice;
    } catch (const std::exception& error) {
        std::cerr << "clrender: error: " << clr::printable(error.what()) << "\n";
        return clr::kExitDevice;
    }
}
