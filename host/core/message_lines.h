// The lines clrender writes on standard error for people, or, with --progress json, for
// programs: then every line on standard error is one JSON object (docs/command-line.md,
// Progress), the errors and warnings too, so that a farm's log parser never meets a line it
// cannot read.
#pragma once

#include <string>

namespace clr {

// From now on, messages are JSON lines (true) or text (false, the default).
void set_json_messages(bool json);
bool json_messages();

// One line, with its newline, for `text` (already printable): "clrender: LEVEL: TEXT" ("clrender:
// TEXT" for "info"), or {"level":"LEVEL","message":"TEXT"} (plus "exit_code" when not 0).
std::string message_line(const std::string& level, const std::string& text, int exit_code = 0);

}  // namespace clr
