#include "app/interruption.h"

#include <csignal>
#include <cstring>

namespace clr {
namespace {

volatile std::sig_atomic_t received_signal = 0;

extern "C" void record_signal(int signal_number) { received_signal = signal_number; }

}  // namespace

Interrupted::Interrupted(int signal_number)
    : Error(std::string("interrupted by ") + (signal_number == SIGINT ? "SIGINT (Ctrl-C)" : "SIGTERM") +
                "; complete frames were kept, nothing partial was left (rerun with --resume to skip written frames)",
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

void throw_if_interrupted() {
    if (received_signal != 0) throw Interrupted(received_signal);
}

}  // namespace clr
