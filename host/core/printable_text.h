// Text that clrender prints about files it was given: names and messages may hold any byte
// (a file name with a newline, an encoder's log with terminal escape sequences), and must
// neither break the one-line form of a message nor drive the terminal.
#pragma once

#include <string>

namespace clr {

// `text` with every control character (bytes below 0x20, and 0x7F) written as \xNN; other
// bytes, UTF-8 included, stay as they are. Escaping twice changes nothing more.
std::string escape_control_characters(const std::string& text);

}  // namespace clr
