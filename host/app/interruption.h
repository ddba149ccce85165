// Ctrl-C (SIGINT) and SIGTERM in the middle of a render. The handler only records the
// signal; the frame loop checks between frames and unwinds, so every output is either
// complete under its final name or not there at all (temporary files are removed on the way
// out), and frames already written stay for a rerun with --resume. A second signal ends the
// process at once.
#pragma once

#include "core/errors.h"

namespace clr {

class Interrupted : public Error {
public:
    explicit Interrupted(int signal_number);
};

void install_interruption_handlers();

// Throws Interrupted when a signal has arrived since install_interruption_handlers().
void throw_if_interrupted();

}  // namespace clr
