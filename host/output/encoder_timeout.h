// How long the video encoder may make no progress (read no frame data, or, after the last
// frame, not grow its output) before clrender gives up on it: $CLRENDER_ENCODER_TIMEOUT in
// seconds, 60 by default. Generous, because a loaded machine or a slow preset can pause an
// encoder for seconds; tests set it to a second or two.
#pragma once

#include <chrono>
#include <string>

namespace clr {

using Seconds = std::chrono::duration<double>;

// Throws UsageError, naming the variable, unless it is unset, empty or a positive number.
Seconds encoder_stall_timeout();

// "60", "1.5": the timeout as error messages show it.
std::string seconds_text(Seconds seconds);

}  // namespace clr
