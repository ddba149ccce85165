// A helper program (the video encoder, the video checker) run as a child in its own process
// group, so that it and anything it starts can be stopped together and nothing outlives
// clrender. Every wait on it is non-blocking or bounded, so that a program that hangs can
// never hang clrender.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

namespace clr {

class ChildProcess {
public:
    // Starts arguments[0] (a path; never through a shell), or `program` where one is given
    // (arguments[0] then only names it, in messages and in the process list), with the given
    // descriptors as its stdin, stdout and stderr (-1: /dev/null), in a new process group, with
    // default signal handling, and clrender's environment with `more_environment` ("NAME=value")
    // added. Throws OutputError when it cannot be started.
    ChildProcess(const std::vector<std::string>& arguments, int stdin_fd, int stdout_fd, int stderr_fd,
                 const std::string& program = "", const std::vector<std::string>& more_environment = {});
    ~ChildProcess();  // stop()s a program still running
    ChildProcess(const ChildProcess&) = delete;
    ChildProcess& operator=(const ChildProcess&) = delete;

    // The program's wait status once it has exited (then reaped, and whatever it left running
    // in its group killed), nullopt while it runs. Never blocks.
    std::optional<int> poll_exit();

    // Stops the whole process group: SIGTERM, a short grace, then SIGKILL; reaps the program
    // and returns its wait status (0 if it was reaped already). A program that cleans up after
    // itself on SIGTERM (clrender itself, rendering a video for the viewer) is given longer.
    int stop() noexcept { return stop(kStopGrace); }
    int stop(std::chrono::milliseconds grace) noexcept;

    // A program that ignores SIGTERM (or is slow to act on it) gets this long before SIGKILL.
    static constexpr std::chrono::milliseconds kStopGrace{500};

    bool running() const { return pid_ > 0; }

private:
    bool has_exited() const;  // without reaping it
    int reap() noexcept;

    pid_t pid_ = -1;  // also the process group's id
};

// "'ffmpeg' exited with status 1", "'ffmpeg' was killed by signal 9 (Killed)".
std::string describe_exit(const std::string& program, int wait_status);

// Sleeps for `slice_ms` milliseconds, then doubles it up to 100 ms: a quick exit is noticed
// within a millisecond or two, a long wait costs ten wake-ups a second.
void sleep_a_slice(int& slice_ms);

}  // namespace clr
