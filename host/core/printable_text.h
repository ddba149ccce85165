// Text clrender did not write itself (a scene's keys and strings, the parser's quote of the
// file, file names, an image decoder's reason, an encoder's log) made safe to print inside
// clrender's one-line messages. The one escaper for every message and warning. A file must not be able to break the line, forge
// other lines, drive the terminal (C0 and C1 control characters: ESC, CSI), reorder what the
// reader sees (Unicode bidirectional overrides), put invalid UTF-8 on the terminal, or make
// one message megabytes long (a 60 MB key, a 1 MB string before a syntax error).
#pragma once

#include <cstddef>
#include <string>

namespace clr {

// `text` with every byte of a control character (C0, DEL, C1 such as U+009B), a
// bidirectional formatting character (U+061C, U+200E-200F, U+202A-202E, U+2066-2069), an
// invisible format character (soft hyphen U+00AD, U+180E, zero-width U+200B-200D,
// U+2060-2064, the byte order mark U+FEFF) or invalid UTF-8 written as \xNN. Valid UTF-8
// otherwise stays as it is.
std::string printable(const std::string& text);

// `text` itself when it has at most `most` characters (UTF-8 code points); otherwise its
// first and last parts with " ... " between them, `most` characters in all, never cutting a
// character in two. Both ends stay: the start says where, the end usually says what.
std::string shortened(const std::string& text, std::size_t most);

// Longest location and detail in a scene message: a few lines of a terminal.
constexpr std::size_t kLongestLocation = 160;
constexpr std::size_t kLongestDetail = 400;

}  // namespace clr
