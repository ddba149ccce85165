// What main() says and returns for an exception that ends a run: the one error line and the
// exit code (README, Exit codes). Expected failures are typed where they happen (core/errors.h);
// anything else that reaches here is a bug in clrender and says so, rather than passing for a
// scene, device or output problem.
#pragma once

#include <exception>
#include <string>

namespace clr {

struct ExitStatus {
    int code = 0;
    // The error line, without its newline, control characters escaped; then, for an error with
    // lines under it (the devices there are), each of them on a line of its own, indented.
    std::string message;
    std::string problem;  // the message after "clrender: error: " (its lines under it too)
};

// The status for `failure` (a non-null exception_ptr, as std::current_exception() gives):
// - clr::Error: its own code and message, and the lines under it;
// - an OpenCL error (cl::Error) that no layer typed: exit 3, as the device failed;
// - std::bad_alloc, or a thread that cannot be started (std::system_error from std::thread):
//   exit 6, out of memory: the machine's limit, not the scene's fault nor the device's;
// - anything else: exit 5, an internal error, with a request to report it.
ExitStatus exit_status_for(std::exception_ptr failure);

}  // namespace clr
