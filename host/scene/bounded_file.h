// Reading an input file whose size a user (or an attacker) controls: the scene, or an image.
// Only regular files are read, their size is checked from fstat before a byte is read, and no
// more than the limit (plus one byte, to notice a file that grew) is ever read. A FIFO, a
// device such as /dev/zero or a socket is refused at once: it has no size to check, and a
// FIFO without a writer would block the open forever, so the file is opened non-blocking.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace clr {

// Why a file was not read, as a short reason ("no such file", "it is a folder", ...). The
// caller adds which file it was and what it was for.
class BoundedFileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The whole content of the regular file at `path`, at most `max_bytes` long.
// Throws BoundedFileError when the file is missing, not a regular file, larger than
// `max_bytes` (by fstat, or by what reading found), or cannot be read.
std::string read_bounded_file(const std::string& path, std::uint64_t max_bytes);
// The same as bytes, for binary files (images).
std::vector<unsigned char> read_bounded_bytes(const std::string& path, std::uint64_t max_bytes);

// A byte count for messages: "512 bytes", "3.5 MiB", "2 GiB".
std::string describe_bytes(std::uint64_t bytes);

}  // namespace clr
