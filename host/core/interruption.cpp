#include "core/interruption.h"

#include "core/message_lines.h"

#include <fcntl.h>
#include <sys/time.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstring>

namespace clr {
namespace {

// Lock-free, so the handler may store it, and atomic, so other threads see the store.
std::atomic<int> received_signal{0};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs a lock-free flag");
// Whether some thread has begun the orderly stop (the frame loop, a band, the encoder's wait).
std::atomic<bool> stop_begun{false};
// Standard error as it was at installation: a build may have it redirected into a capture
// (device/stderr_capture.h) when the watchdog speaks.
int original_stderr = STDERR_FILENO;
bool stderr_is_terminal = false;  // where a progress bar's line may be open

// A signal's orderly stop is acted on between bands, frames and encoder slices, each well under
// a second. Some steps cannot be interrupted: a cold OpenCL build inside the driver (which,
// short of memory, may also wait forever on a lock of its own), one huge image's decode. When
// no thread has begun the stop this long after the signal, the watchdog ends the process.
constexpr long kMillisecondsUntilForcedStop = 500;
// Once the orderly stop has begun (stopping the encoder takes up to about a second), it gets
// this long before the watchdog ends the process all the same.
constexpr long kMillisecondsForOrderlyStop = 5000;

// Arms the watchdog (SIGALRM) `milliseconds` from now, replacing any earlier time.
void arm_watchdog(long milliseconds) {
    struct itimerval timer;
    std::memset(&timer, 0, sizeof timer);
    timer.it_value.tv_sec = milliseconds / 1000;
    timer.it_value.tv_usec = milliseconds % 1000 * 1000;
    ::setitimer(ITIMER_REAL, &timer, nullptr);
}

void write_all(int fd, const char* text) {
    std::size_t left = std::strlen(text);
    while (left > 0) {
        const ssize_t written = ::write(fd, text, left);
        if (written <= 0) return;
        text += written;
        left -= static_cast<std::size_t>(written);
    }
}

extern "C" void record_signal(int signal_number) {
    int none = 0;
    if (received_signal.compare_exchange_strong(none, signal_number)) arm_watchdog(kMillisecondsUntilForcedStop);
}

std::atomic<pid_t> child_groups[16];
static_assert(std::atomic<pid_t>::is_always_lock_free, "signal handlers read the child groups");

// Async-signal-safe: only write(), kill() and _exit() (setitimer() in record_signal is a plain system call).
extern "C" void force_stop(int) {
    const int signal_number = received_signal.load();
    if (signal_number == 0) return;
    const char* name = signal_number == SIGINT ? "SIGINT (Ctrl-C)" : signal_number == SIGHUP ? "SIGHUP (terminal closed)" : "SIGTERM";
    const char* code = signal_number == SIGINT ? "130" : signal_number == SIGHUP ? "129" : "143";
    const bool json = json_messages();  // core/message_lines.h: the text needs no escaping
    if (stderr_is_terminal && !json) write_all(original_stderr, "\n");  // after a bar's open line
    write_all(original_stderr, json ? "{\"level\":\"error\",\"message\":\"interrupted by " : "clrender: error: interrupted by ");
    write_all(original_stderr, name);
    write_all(original_stderr,
              "; a step that cannot be interrupted (the OpenCL driver building the kernels, say) did not end, so "
              "clrender stopped at once (no output of the unfinished step was written; temporary files are removed "
              "by the next run)");
    if (json) {
        write_all(original_stderr, "\",\"exit_code\":");
        write_all(original_stderr, code);
        write_all(original_stderr, "}");
    }
    write_all(original_stderr, "\n");
    kill_child_groups();
    ::_exit(128 + signal_number);
}

// The orderly stop has begun: the watchdog waits longer, so that it can finish.
void note_stop_begun() {
    if (!stop_begun.exchange(true)) arm_watchdog(kMillisecondsForOrderlyStop);
}

void set_action(int signal_number, void (*handler)(int), int flags) {
    struct sigaction action;
    std::memset(&action, 0, sizeof action);
    action.sa_handler = handler;
    sigemptyset(&action.sa_mask);
    action.sa_flags = flags;
    sigaction(signal_number, &action, nullptr);
}

std::string signal_name(int signal_number) {
    switch (signal_number) {
        case SIGINT: return "SIGINT (Ctrl-C)";
        case SIGHUP: return "SIGHUP (terminal closed)";
        default: return "SIGTERM";
    }
}

}  // namespace

Interrupted::Interrupted(int signal_number)
    : Error("interrupted by " + signal_name(signal_number) +
                "; the unfinished frame was discarded and no partial file was left (frames of an animation "
                "already written are kept; with -o and a frame pattern, --resume skips them)",
            static_cast<ExitCode>(128 + signal_number)) {}

void install_interruption_handlers() {
    const int saved = ::fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 3);
    if (saved >= 0) original_stderr = saved;
    stderr_is_terminal = ::isatty(STDERR_FILENO) == 1;
    set_action(SIGALRM, force_stop, 0);
    // A second signal takes the default action: exit now.
    for (int signal_number : {SIGINT, SIGTERM, SIGHUP}) set_action(signal_number, record_signal, SA_RESETHAND);
    // A write to a closed pipe (stderr piped into `head -1`, an encoder that quit) and a write
    // beyond `ulimit -f` would kill clrender mid-write by default, leaving its temporary files
    // and encoder behind. Ignored, the write fails instead (EPIPE, EFBIG): an output write
    // becomes an output error (exit code 4), a message to a closed stderr is lost.
    set_action(SIGPIPE, SIG_IGN, 0);
    set_action(SIGXFSZ, SIG_IGN, 0);
}

bool interruption_requested() {
    if (received_signal.load() == 0) return false;
    note_stop_begun();
    return true;
}

void track_child_group(pid_t group) {
    for (std::atomic<pid_t>& slot : child_groups) {
        pid_t empty = 0;
        if (slot.compare_exchange_strong(empty, group)) return;
    }
}

void untrack_child_group(pid_t group) {
    for (std::atomic<pid_t>& slot : child_groups) {
        pid_t expected = group;
        if (slot.compare_exchange_strong(expected, 0)) return;
    }
}

void kill_child_groups() noexcept {
    for (std::atomic<pid_t>& slot : child_groups)
        if (const pid_t group = slot.load(); group > 0) ::kill(-group, SIGKILL);
}

void throw_if_interrupted() {
    if (const int signal_number = received_signal.load()) {
        note_stop_begun();
        throw Interrupted(signal_number);
    }
}

}  // namespace clr
