// `clrender view` started as a user starts it (--no-browser --port 0), for the tests that talk
// HTTP to it: the address it prints, an HTTP client for it, and its end (a signal, its exit
// code and what it printed).
#pragma once

#include <sys/types.h>

#include <httplib.h>

#include <memory>
#include <string>

namespace clr::testing {

class ViewerProcess {
public:
    // Starts `clrender view <arguments> --no-browser --port 0` in `folder` and waits (up to two
    // minutes: the first start builds the program) for the line with its address. Check
    // started() before using it; output() says why it did not start.
    // `environment` ("PATH=...") is set for it; with `open_browser`, --no-browser is left out;
    // `program` is the clrender started ("": the one built with the tests).
    ViewerProcess(const std::string& arguments, const std::string& folder, const std::string& environment = "",
                  bool open_browser = false, const std::string& program = "");
    ~ViewerProcess();  // SIGKILLs it if it still runs

    bool started() const { return port_ > 0; }
    pid_t pid() const { return pid_; }  // -1 once stopped
    int port() const { return port_; }
    const std::string& token() const { return token_; }
    const std::string& address_line() const { return line_; }
    // A client for 127.0.0.1:PORT, which sends the Host header that names it.
    std::unique_ptr<httplib::Client> client() const;
    // "path?token=TOKEN" or "path?QUERY&token=TOKEN".
    std::string with_token(const std::string& path_and_query) const;

    // Sends `signal` and returns the exit code (128 + signal for a clean stop), or -1 when it
    // has not exited within `seconds`.
    int stop(int signal, int seconds = 30);
    // Standard error so far (and standard output after the address line).
    std::string output() const;

private:
    pid_t pid_ = -1;
    int port_ = 0;
    std::string token_;
    std::string line_;
    std::string folder_;
};

}  // namespace clr::testing
