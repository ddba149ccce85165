#include "core/interruption.h"

#include <atomic>
#include <csignal>
#include <cstring>

namespace clr {
namespace {

// Lock-free, so the handler may store it, and atomic, so other threads see the store.
std::atomic<int> received_signal{0};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs a lock-free flag");

extern "C" void record_signal(int signal_number) { received_signal.store(signal_number); }

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
    // A second signal takes the default action: exit now.
    for (int signal_number : {SIGINT, SIGTERM, SIGHUP}) set_action(signal_number, record_signal, SA_RESETHAND);
    // A write to a closed pipe (stderr piped into `head -1`, an encoder that quit) and a write
    // beyond `ulimit -f` would kill clrender mid-write by default, leaving its temporary files
    // and encoder behind. Ignored, the write fails instead (EPIPE, EFBIG): an output write
    // becomes an output error (exit code 4), a message to a closed stderr is lost.
    set_action(SIGPIPE, SIG_IGN, 0);
    set_action(SIGXFSZ, SIG_IGN, 0);
}

bool interruption_requested() { return received_signal.load() != 0; }

void throw_if_interrupted() {
    if (const int signal_number = received_signal.load()) throw Interrupted(signal_number);
}

}  // namespace clr
