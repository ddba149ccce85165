#include "output/full_disk_note.h"

#include <sys/statvfs.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace clr {

std::string full_disk_note(const std::string& path) {
    // The folder's file system: the file itself may never have been made.
    std::string folder = std::filesystem::path(path).parent_path().string();
    if (folder.empty()) folder = ".";
    struct statvfs disk {};
    if (::statvfs(folder.c_str(), &disk) != 0) return "";
    const std::uint64_t free_bytes = static_cast<std::uint64_t>(disk.f_bavail) * disk.f_frsize;
    if (free_bytes >= kNearlyFullDiskBytes) return "";
    return "; the disk holding it has only " + std::to_string(free_bytes / 1024) + " KiB free: it is likely full (" +
           std::strerror(ENOSPC) + ")";
}

}  // namespace clr
