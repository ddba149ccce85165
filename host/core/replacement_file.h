// A file written under a temporary name and then renamed over its final name, so that a reader
// finds the earlier file or the whole new one, never a part (rename() is atomic within one file
// system, so the temporary name must lie in the final file's folder). The one implementation of
// that pattern: the caches' entries (core/cache_entry_folder.h) and every output
// (output/atomic_file.h) build on it. Until it is renamed, the temporary file is removed when
// this object goes: an error or an exception leaves nothing under either name, also when the
// folder was renamed meanwhile (core/folder_entry.h).
#pragma once

#include <sys/types.h>

#include <string>

#include "core/folder_entry.h"

namespace clr {

class ReplacementFile {
public:
    // Creates `temporary_path`, which must not exist (O_EXCL: never writes into a file someone
    // else made under the same name, nor through a symlink), with permissions `mode` less the
    // umask. created() says whether that worked; errno says why not.
    ReplacementFile(std::string temporary_path, mode_t mode);
    // Takes over `temporary_path`, a file another writer made and closed.
    static ReplacementFile adopt(std::string temporary_path);
    ~ReplacementFile();
    ReplacementFile(ReplacementFile&& other) noexcept;
    ReplacementFile& operator=(ReplacementFile&&) = delete;
    ReplacementFile(const ReplacementFile&) = delete;
    ReplacementFile& operator=(const ReplacementFile&) = delete;

    bool created() const { return !temporary_path_.empty(); }
    const std::string& temporary_path() const { return temporary_path_; }
    // Open for writing until close() or release_descriptor(); -1 after.
    int descriptor() const { return descriptor_; }
    // Hands the open descriptor to an owner that closes it (a stdio stream).
    int release_descriptor();
    // Closes the descriptor, after syncing the data to the disk when `sync`; false when a
    // write failed to reach the file (errno says why).
    bool close(bool sync);
    // Renames the (closed) temporary file over `final_path`; false, errno set, when that fails,
    // in which case the temporary file is still removed at the end.
    bool rename_onto(const std::string& final_path);
    // The same where nothing may be replaced: false with errno EEXIST when `final_path` names
    // any directory entry (a file, a folder, a link even to nothing). renameat2's
    // RENAME_NOREPLACE, or link(2) and unlink(2) on a file system without it.
    bool rename_onto_unused(const std::string& final_path);

private:
    ReplacementFile() = default;

    std::string temporary_path_;
    FolderEntry entry_;  // removes the temporary file even from a folder renamed meanwhile
    int descriptor_ = -1;
    bool renamed_ = false;
};

}  // namespace clr
