// The temporary file sits in the final file's folder because rename() is atomic only within
// one file system; its name (temp_files.h) is short and hidden, and recognisable to a later
// run if this one is killed before it can remove it.
#include "output/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>

#include "core/errors.h"
#include "output/output_target.h"
#include "output/temp_files.h"

namespace clr {
namespace {

OutputError output_error(const std::string& final_path, const std::string& what, int error_number) {
    return OutputError(final_path + ": " + what + ": " + std::strerror(error_number));
}

// After a rename, the folder's entry must reach the disk too, or a crash could bring back the
// old file. Best effort: the file is in place either way, and some file systems cannot sync
// a folder.
void sync_folder_of(const std::string& path) {
    const std::string folder = std::filesystem::path(path).parent_path().string();
    const int fd = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    ::fsync(fd);
    ::close(fd);
}

}  // namespace

AtomicFile::AtomicFile(std::string final_path) : final_path_(std::move(final_path)) {
    if (final_path_.empty() || std::filesystem::path(final_path_).filename().empty()) {
        throw OutputError("'" + final_path_ + "' is not a file name");
    }
    target_path_ = resolve_output_target(final_path_);
    // Mode 0666 (less the umask) gives the permissions any newly written file would get.
    const std::string temp_path = create_under_temp_name(target_path_, [this](const std::string& try_path) {
        temp_.emplace(try_path, 0666);
        return temp_->created();
    });
    if (temp_path.empty()) throw OutputError(final_path_ + ": " + temp_creation_failure(errno));
    stream_ = ::fdopen(temp_->descriptor(), "wb");
    if (!stream_) throw output_error(final_path_, "cannot open a stream", errno);
    temp_->release_descriptor();  // the stream closes it
}

std::unique_ptr<AtomicFile> AtomicFile::adopt(const std::string& finished_temp_path, std::string final_path) {
    std::unique_ptr<AtomicFile> file(new AtomicFile());
    file->final_path_ = std::move(final_path);
    file->temp_.emplace(ReplacementFile::adopt(finished_temp_path));  // removed unless committed
    file->target_path_ = resolve_output_target(file->final_path_);
    file->completed_ = true;
    return file;
}

AtomicFile::~AtomicFile() {
    if (stream_) std::fclose(stream_);
}

void AtomicFile::write(const void* data, std::size_t size) {
    if (!stream_) throw OutputError(final_path_ + ": write after the file was completed");
    if (size > 0 && std::fwrite(data, 1, size, stream_) != size) throw output_error(final_path_, "write failed", errno);
}

void AtomicFile::complete() {
    if (completed_) return;
    if (!stream_) throw OutputError(final_path_ + ": completed after a failure");
    // fsync before rename: otherwise a crash soon after could leave the new name pointing
    // at a file whose data never reached the disk, which is the truncated output we promise
    // never to leave.
    const bool flushed = std::fflush(stream_) == 0 && ::fsync(::fileno(stream_)) == 0;
    int error_number = errno;
    const bool closed = std::fclose(stream_) == 0;
    stream_ = nullptr;
    if (flushed && !closed) error_number = errno;
    if (!flushed || !closed) throw output_error(final_path_, "write failed", error_number);
    completed_ = true;
}

void AtomicFile::commit() {
    if (committed_) throw OutputError(final_path_ + ": committed twice");
    complete();
    if (!temp_->rename_onto(target_path_)) throw output_error(final_path_, "cannot move the finished file into place", errno);
    committed_ = true;
    sync_folder_of(target_path_);
}

}  // namespace clr
