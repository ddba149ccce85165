// A file to be removed later, found through its folder held open: a temporary file can then be
// removed even after someone renamed or moved the folder it lies in during a long render, where
// removing it by path would miss it and leave it behind.
#pragma once

#include <string>

namespace clr {

class FolderEntry {
public:
    FolderEntry() = default;
    // Holds the folder of `path` open (O_PATH: no read access needed); when that fails, remove()
    // falls back to the path.
    explicit FolderEntry(const std::string& path);
    ~FolderEntry();
    FolderEntry(FolderEntry&& other) noexcept;
    FolderEntry& operator=(FolderEntry&& other) noexcept;
    FolderEntry(const FolderEntry&) = delete;
    FolderEntry& operator=(const FolderEntry&) = delete;

    // Removes the file (unlinkat in the folder held open); false when it was not there.
    bool remove() const;
    // Opens the file with open(2)'s `flags` and `mode` in the folder held open (openat), so
    // that the file is made in the folder remove() will look in, even when the folder is
    // renamed in between; by its path when the folder could not be held.
    int open(int flags, unsigned mode) const;

private:
    void release();

    std::string path_;
    std::string name_;
    int folder_ = -1;
};

}  // namespace clr
