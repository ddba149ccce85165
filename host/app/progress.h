// Progress of a long render on a terminal: frames done, frames per second and the time left.
// Silent when asked to be, or when standard error is not a terminal (logs stay clean).
#pragma once

#include <string>

#include "core/stopwatch.h"

namespace clr {

class Progress {
public:
    Progress(int total_frames, bool quiet);
    void frame_done();
    void finish();  // ends the progress line

private:
    void draw() const;

    int total_;
    int done_ = 0;
    bool enabled_;
    Stopwatch since_start_;
};

// "1:05" or "12:03:07": a duration for people.
std::string format_duration(double seconds);

}  // namespace clr
