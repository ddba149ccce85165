// The temporary file sits in the final file's folder because rename() is atomic only within
// one file system; a name starting with '.' keeps it out of casual listings meanwhile.
#include "output/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>

#include "core/errors.h"

namespace clr {
namespace {

// "<folder>/.<name>.tmp-<pid>-<n>": the process id and a per-process counter keep writers
// in different processes (a render farm sharing a folder) and threads from colliding.
std::string temp_path_beside(const std::string& final_path) {
    static std::atomic<unsigned> counter{0};
    const std::filesystem::path path(final_path);
    const std::string name = "." + path.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                             std::to_string(counter++);
    return (path.parent_path() / name).string();
}

OutputError output_error(const std::string& final_path, const std::string& what, int error_number) {
    return OutputError(final_path + ": " + what + ": " + std::strerror(error_number));
}

}  // namespace

AtomicFile::AtomicFile(std::string final_path) : final_path_(std::move(final_path)) {
    if (final_path_.empty() || std::filesystem::path(final_path_).filename().empty()) {
        throw OutputError("'" + final_path_ + "' is not a file name");
    }
    temp_path_ = temp_path_beside(final_path_);
    // O_EXCL: never write into a file someone else created under the same temporary name.
    // Mode 0666 (less the umask) gives the permissions any newly written file would get.
    const int fd = ::open(temp_path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) throw output_error(final_path_, "cannot create a file in its folder", errno);
    stream_ = ::fdopen(fd, "wb");
    if (!stream_) {
        const int error_number = errno;
        ::close(fd);
        std::remove(temp_path_.c_str());
        throw output_error(final_path_, "cannot open a stream", error_number);
    }
}

AtomicFile::~AtomicFile() {
    if (stream_) std::fclose(stream_);
    if (!committed_) std::remove(temp_path_.c_str());
}

void AtomicFile::write(const void* data, std::size_t size) {
    if (!stream_) throw OutputError(final_path_ + ": write after commit");
    if (size > 0 && std::fwrite(data, 1, size, stream_) != size) throw output_error(final_path_, "write failed", errno);
}

void AtomicFile::commit() {
    if (!stream_) throw OutputError(final_path_ + ": committed twice");
    // fsync before rename: otherwise a crash soon after could leave the new name pointing
    // at a file whose data never reached the disk, which is the truncated output we promise
    // never to leave.
    const bool flushed = std::fflush(stream_) == 0 && ::fsync(::fileno(stream_)) == 0;
    int error_number = errno;
    const bool closed = std::fclose(stream_) == 0;
    stream_ = nullptr;
    if (flushed && !closed) error_number = errno;
    if (!flushed || !closed) throw output_error(final_path_, "write failed", error_number);
    if (std::rename(temp_path_.c_str(), final_path_.c_str()) != 0) {
        throw output_error(final_path_, "cannot move the finished file into place", errno);
    }
    committed_ = true;
}

}  // namespace clr
