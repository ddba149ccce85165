#include "core/folder_entry.h"

#include <fcntl.h>
#include <unistd.h>

#include <utility>

namespace clr {

FolderEntry::FolderEntry(const std::string& path) : path_(path) {
    const std::size_t slash = path.find_last_of('/');
    const std::string folder = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
    name_ = slash == std::string::npos ? path : path.substr(slash + 1);
    folder_ = ::open(folder.c_str(), O_PATH | O_DIRECTORY | O_CLOEXEC);
}

FolderEntry::~FolderEntry() { release(); }

FolderEntry::FolderEntry(FolderEntry&& other) noexcept
    : path_(std::move(other.path_)), name_(std::move(other.name_)), folder_(std::exchange(other.folder_, -1)) {}

FolderEntry& FolderEntry::operator=(FolderEntry&& other) noexcept {
    if (this != &other) {
        release();
        path_ = std::move(other.path_);
        name_ = std::move(other.name_);
        folder_ = std::exchange(other.folder_, -1);
    }
    return *this;
}

void FolderEntry::release() {
    if (folder_ >= 0) ::close(folder_);
    folder_ = -1;
}

int FolderEntry::open(int flags, unsigned mode) const {
    if (folder_ >= 0) return ::openat(folder_, name_.c_str(), flags, static_cast<mode_t>(mode));
    return ::open(path_.c_str(), flags, static_cast<mode_t>(mode));
}

bool FolderEntry::remove() const {
    if (path_.empty()) return false;
    if (folder_ >= 0) return ::unlinkat(folder_, name_.c_str(), 0) == 0;
    return ::unlink(path_.c_str()) == 0;
}

}  // namespace clr
