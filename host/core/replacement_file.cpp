#include "core/replacement_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <utility>

namespace clr {

ReplacementFile::ReplacementFile(std::string temporary_path, mode_t mode) {
    // The folder is held open first and the file made in it: opening the folder by its path
    // after making the file could find it renamed in between, and the file would then be
    // left behind wherever the folder went.
    FolderEntry entry(temporary_path);
    descriptor_ = entry.open(O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, mode);
    if (descriptor_ >= 0) {
        entry_ = std::move(entry);
        temporary_path_ = std::move(temporary_path);
    }
}

ReplacementFile ReplacementFile::adopt(std::string temporary_path) {
    ReplacementFile file;
    file.entry_ = FolderEntry(temporary_path);
    file.temporary_path_ = std::move(temporary_path);
    return file;
}

ReplacementFile::ReplacementFile(ReplacementFile&& other) noexcept
    : temporary_path_(std::move(other.temporary_path_)),
      entry_(std::move(other.entry_)),
      descriptor_(std::exchange(other.descriptor_, -1)),
      renamed_(other.renamed_) {
    other.temporary_path_.clear();
}

ReplacementFile::~ReplacementFile() {
    if (descriptor_ >= 0) ::close(descriptor_);
    if (created() && !renamed_) entry_.remove();
}

int ReplacementFile::release_descriptor() { return std::exchange(descriptor_, -1); }

bool ReplacementFile::close(bool sync) {
    const int descriptor = std::exchange(descriptor_, -1);
    const bool synced = !sync || ::fsync(descriptor) == 0;
    const int sync_error = errno;
    const bool closed = ::close(descriptor) == 0;
    if (!synced) errno = sync_error;
    return synced && closed;
}

bool ReplacementFile::rename_onto_unused(const std::string& final_path) {
    if (::renameat2(AT_FDCWD, temporary_path_.c_str(), AT_FDCWD, final_path.c_str(), RENAME_NOREPLACE) == 0) {
        renamed_ = true;
        return true;
    }
    if (errno != EINVAL && errno != ENOSYS && errno != ENOTSUP) return false;
    // No RENAME_NOREPLACE here (some network and FUSE file systems): a hard link is made only
    // under a free name, and the temporary name is then removed.
    if (::link(temporary_path_.c_str(), final_path.c_str()) != 0) return false;
    renamed_ = true;
    entry_.remove();
    return true;
}

bool ReplacementFile::rename_onto(const std::string& final_path) {
    if (std::rename(temporary_path_.c_str(), final_path.c_str()) != 0) return false;
    renamed_ = true;
    return true;
}

}  // namespace clr
