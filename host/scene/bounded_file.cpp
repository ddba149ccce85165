#include "scene/bounded_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace clr {
namespace {

// Closes the descriptor however the read ends.
class FileDescriptor {
public:
    explicit FileDescriptor(int fd) : fd_(fd) {}
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;
    ~FileDescriptor() {
        if (fd_ >= 0) ::close(fd_);
    }
    int get() const { return fd_; }

private:
    int fd_;
};

std::string kind_of(mode_t mode) {
    if (S_ISDIR(mode)) return "it is a folder";
    if (S_ISFIFO(mode)) return "it is a FIFO (named pipe), not a regular file";
    if (S_ISCHR(mode)) return "it is a character device, not a regular file";
    if (S_ISBLK(mode)) return "it is a block device, not a regular file";
    if (S_ISSOCK(mode)) return "it is a socket, not a regular file";
    return "it is not a regular file";
}

std::string too_large(std::uint64_t size, std::uint64_t max_bytes) {
    std::string size_text = describe_bytes(size), limit_text = describe_bytes(max_bytes);
    // Rounded alike ("1 GiB, more than the limit of 1 GiB"), the figures are given in bytes.
    if (size_text == limit_text) {
        size_text = std::to_string(size) + " bytes";
        limit_text += " (" + std::to_string(max_bytes) + " bytes)";
    }
    return "the file is " + size_text + ", more than the limit of " + limit_text;
}

}  // namespace

// Whole units where they are exact ("64 MiB"), two decimals at most otherwise ("2.25 GiB"),
// and bytes for a small odd count, which a rounded "4.0 KiB" would misstate.
std::string describe_bytes(std::uint64_t bytes) {
    static const char* const kUnits[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
    const auto in_bytes = [&] { return std::to_string(bytes) + (bytes == 1 ? " byte" : " bytes"); };
    if (bytes < 1024) return in_bytes();
    int unit = 0;
    std::uint64_t scale = 1024;
    while (unit < 5 && bytes / scale >= 1024) {
        scale *= 1024;
        ++unit;
    }
    if (bytes % scale != 0 && bytes < (std::uint64_t(1) << 20)) return in_bytes();
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", static_cast<double>(bytes) / static_cast<double>(scale));
    std::string number = text;
    number.erase(number.find_last_not_of('0') + 1);
    if (number.back() == '.') number.pop_back();
    return number + " " + kUnits[unit];
}

namespace {

// std::string for text, std::vector<unsigned char> for binary files.
template <typename Bytes>
Bytes read_bounded(const std::string& path, std::uint64_t max_bytes) {
    // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer. It changes
    // nothing for a regular file, the only kind read.
    const FileDescriptor file(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY));
    if (file.get() < 0) {
        const int error = errno;
        if (error == ENOENT) throw BoundedFileError("no such file");
        // A socket cannot be opened at all (ENXIO, "No such device or address", as for a
        // device without its driver), though it is there: it is named for what it is.
        struct stat status {};
        if (::stat(path.c_str(), &status) == 0 && !S_ISREG(status.st_mode) && !S_ISDIR(status.st_mode))
            throw BoundedFileError(kind_of(status.st_mode));
        throw BoundedFileError(std::string("cannot open: ") + std::strerror(error));
    }
    struct stat status {};
    if (::fstat(file.get(), &status) != 0) throw BoundedFileError(std::string("cannot read: ") + std::strerror(errno));
    if (!S_ISREG(status.st_mode)) throw BoundedFileError(kind_of(status.st_mode));
    const auto size = static_cast<std::uint64_t>(status.st_size);
    if (size > max_bytes) throw BoundedFileError(too_large(size, max_bytes));

    // The size may change while the file is read (or be wrong, as for files under /proc):
    // read until the end, but never past the limit plus the one byte that shows it is passed.
    Bytes bytes;
    bytes.reserve(static_cast<std::size_t>(size));
    char chunk[1 << 16];
    while (bytes.size() <= max_bytes) {
        const std::uint64_t room = max_bytes - bytes.size();  // no overflow, even for a limit of 2^64 - 1
        const std::size_t wanted = room >= sizeof chunk ? sizeof chunk : static_cast<std::size_t>(room) + 1;
        const ssize_t got = ::read(file.get(), chunk, wanted);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) throw BoundedFileError(std::string("cannot read: ") + std::strerror(errno));
        if (got == 0) return bytes;
        bytes.insert(bytes.end(), chunk, chunk + got);
    }
    throw BoundedFileError("the file grew past the limit of " + describe_bytes(max_bytes) + " while it was read");
}

}  // namespace

std::string read_bounded_file(const std::string& path, std::uint64_t max_bytes) {
    return read_bounded<std::string>(path, max_bytes);
}

std::vector<unsigned char> read_bounded_bytes(const std::string& path, std::uint64_t max_bytes) {
    return read_bounded<std::vector<unsigned char>>(path, max_bytes);
}

}  // namespace clr
