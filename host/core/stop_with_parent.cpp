#include "core/stop_with_parent.h"

#include <signal.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <atomic>
#include <charconv>
#include <cstdlib>
#include <cstring>

namespace clr {
namespace {

std::atomic<bool> parent_gone{false};
static_assert(std::atomic<bool>::is_always_lock_free, "used in a signal handler");

// The system sends the parent-death signal again each time the process is handed to another
// thread of the dying parent (the viewer has dozens), and clrender takes a second SIGTERM as
// "exit now", leaving its unfinished files: the parent's end is one SIGTERM, however often the
// signal comes. Async-signal-safe: an atomic exchange and kill().
void on_parent_gone(int) {
    if (!parent_gone.exchange(true)) ::kill(::getpid(), SIGTERM);
}

}  // namespace

std::string stop_with_parent_entry() {
    return std::string(kStopWithParentVariable) + "=" + std::to_string(::getpid());
}

void stop_with_parent_from_environment() {
    const char* value = std::getenv(kStopWithParentVariable);
    if (!value) return;
    pid_t parent = 0;
    const char* end = value + std::strlen(value);
    const auto read = std::from_chars(value, end, parent);
    ::unsetenv(kStopWithParentVariable);  // for this process alone, not for what it starts
    if (read.ec != std::errc() || read.ptr != end || parent <= 1) return;
    // A real-time signal of its own: SIGUSR2 is PoCL's, and no library here uses this one.
    const int signal_number = SIGRTMIN + 1;
    struct sigaction action {};
    action.sa_handler = on_parent_gone;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    if (::sigaction(signal_number, &action, nullptr) != 0 || ::prctl(PR_SET_PDEATHSIG, signal_number) != 0) return;
    // Asked after the start: a parent that ended before it has made this process another's child.
    if (::getppid() != parent) on_parent_gone(signal_number);
}

}  // namespace clr
