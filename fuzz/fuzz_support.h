// What the fuzz targets share: a private folder for the files they hand to the loaders, and
// a way to report a broken expectation as a crash, which libFuzzer then keeps as an input.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace clr::fuzz {

// A fresh folder for this process (mkdtemp under $TMPDIR, else /tmp), made on first use and
// removed when the process exits normally. Several fuzzing processes never share one.
const std::string& work_folder();

// Writes `size` bytes to `path`, replacing the file. Aborts if it cannot: a fuzzer that
// cannot write its input would only report false results.
void write_file(const std::string& path, const void* data, std::size_t size);

// Whether `message` is fit to print as (part of) one line of a terminal by the rule clrender's
// escaper applies (core/printable_text.h): nothing in it that printable() would escape (control
// characters, bidirectional overrides, invalid UTF-8). Messages quote file contents (keys,
// chunk names), so a file must not be able to forge output lines or drive the terminal
// through them.
bool is_one_printable_line(const std::string& message);

// Prints "clrender fuzz: BUG: <what>: <detail>" and aborts, so that libFuzzer reports a
// crash and saves the input that caused it.
[[noreturn]] void report_bug(const std::string& what, const std::string& detail);

}  // namespace clr::fuzz
