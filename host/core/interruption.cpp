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

}  // namespace

Interrupted::Interrupted(int signal_number)
    : Error(std::string("interrupted by ") + (signal_number == SIGINT ? "SIGINT (Ctrl-C)" : "SIGTERM") +
                "; the unfinished frame was discarded and no partial file was left (frames of an animation "
                "already written are kept: rerun with --resume to skip them)",
            static_cast<ExitCode>(128 + signal_number)) {}

void install_interruption_handlers() {
    struct sigaction action;
    std::memset(&action, 0, sizeof action);
    action.sa_handler = record_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;  // a second signal takes the default action: exit now
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

bool interruption_requested() { return received_signal.load() != 0; }

void throw_if_interrupted() {
    if (const int signal_number = received_signal.load()) throw Interrupted(signal_number);
}

}  // namespace clr
