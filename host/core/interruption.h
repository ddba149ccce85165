// Ctrl-C (SIGINT), SIGTERM and SIGHUP (the terminal closed) in the middle of a run. It lives in core/ because every layer
// that waits (the frame loop, the renderer's bands, the video encoder) must be able to stop.
// The handler only records the signal; the frame loop checks between frames and unwinds, so every output is either
// complete under its final name or not there at all (temporary files are removed on the way
// out), and frames already written stay for a rerun with --resume. A second signal ends the
// process at once. A watchdog ends it too, with the signal's exit code and one error line, when
// no thread has begun the orderly stop half a second after the signal (a step that cannot be
// interrupted: a cold OpenCL build, which short of memory may wait forever on a lock inside the
// driver), or when the orderly stop has not ended five seconds after it began.
#pragma once

#include <sys/types.h>

#include "core/errors.h"

namespace clr {

class Interrupted : public Error {
public:
    explicit Interrupted(int signal_number);
};

// Records SIGINT, SIGTERM and SIGHUP from now on, and ignores SIGPIPE and SIGXFSZ (so that
// writes to a closed pipe or beyond the file size limit fail instead of killing clrender).
// Called first thing in a run: a signal while the scene loads is acted upon at the next check.
void install_interruption_handlers();

// Whether SIGINT, SIGTERM or SIGHUP has arrived since install_interruption_handlers(). Safe to call
// from any thread; long waits (a frame's bands, the video encoder's pipe) poll it.
bool interruption_requested();

// Throws Interrupted when a signal has arrived since install_interruption_handlers().
void throw_if_interrupted();

// The process groups of running helper programs (the video encoder, its checker): a stop that
// cannot wait for the orderly one (the watchdog, a crash in the driver) kills them first, so
// that none outlives clrender. At most 16 at a time; more are not tracked.
void track_child_group(pid_t group);
void untrack_child_group(pid_t group);
// Async-signal-safe: SIGKILL to every tracked group.
void kill_child_groups() noexcept;

}  // namespace clr
