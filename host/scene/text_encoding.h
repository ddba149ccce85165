// Recognising scene text saved in an encoding clrender does not read. Editors on Windows
// (Notepad's "Unicode", PowerShell's `>`) save UTF-16; JSON parsers then stop at the first
// NUL byte with a message about that byte, which does not tell the user what to do.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace clr {

// "UTF-16 (little-endian)", "UTF-32 (big-endian)", ... when `text` starts with that
// encoding's byte order mark, or, without one, with the NUL bytes that ASCII characters
// (every JSON text starts with one) have in it (RFC 4627, section 3). nullopt otherwise.
std::optional<std::string> wide_unicode_encoding(std::string_view text);

// Why `text` is not the text of an OBJ or .mtl file though it may be one saved another way:
// UTF-16 or UTF-32 (whose NUL bytes would read as unknown statements), compressed (gzip, zstd,
// xz, bzip2, LZ4) or archived (ZIP, 7-Zip), each known by its first bytes. "" when none.
std::string saved_text_problem(std::string_view text);

}  // namespace clr
