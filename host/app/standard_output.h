// Whether everything clrender printed on standard output (--check's summary, --list-devices,
// --frame-count, --stats -, --explain-pixel, --help) reached it. Output is buffered, so a full
// disk or a closed pipe behind standard output shows only when the buffer is flushed: a run that
// did not check would exit 0 with its output cut short.
#pragma once

#include <string>

namespace clr {

// Flushes standard output (C++ and C streams); "" when every byte was written, else what failed,
// e.g. "No space left on device".
std::string flush_standard_output();

}  // namespace clr
