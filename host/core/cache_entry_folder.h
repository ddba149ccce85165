// The entries of one cache in its own sub-folder of the cache folder (core/cache_folder.h):
// `<64 hex digits of the key>.<extension>`, written to `<that name>.tmp-<pid>-<n>` and renamed,
// so a reader sees no entry or a whole one. Everything here is best effort: a folder that cannot
// be used, written or filled just means no caching, never an error.
//
// Only files that are provably clrender's are ever removed: in this sub-folder, named by the
// patterns above, regular files (never through a symlink) that start with the cache's magic.
// Anything else there (other names, symlinks, folders, files without the magic) is never
// touched and not counted against the size limit.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "core/cache_entry.h"
#include "core/sha256.h"

namespace clr {

class CacheEntryFolder {
public:
    // A temporary file of ours older than this was left by a run that crashed or was killed.
    static constexpr int kStaleTemporaryMinutes = 10;

    // `root` "" disables the cache; entries go in root/subfolder.
    CacheEntryFolder(std::string root, std::string subfolder, CacheEntryKind kind, std::uint64_t size_limit);

    bool enabled() const { return !root_.empty(); }
    const std::string& root() const { return root_; }
    std::string folder() const { return enabled() ? root_ + "/" + subfolder_ : std::string(); }
    const CacheEntryKind& kind() const { return kind_; }
    // The entry's file for `key`.
    std::string path(const Sha256Digest& key) const;

    // The verified entry for `key`, or nothing. A hit refreshes the entry's modification time,
    // which is what eviction goes by. An entry of ours that fails a check is removed.
    std::optional<CacheEntry> load(const Sha256Digest& key) const;
    // load() for a consumer that may crash on a bad payload (an OpenCL driver given a binary):
    // the entry is moved to a temporary name of ours first, into `aside`, and only put back by
    // give_back() once it proved good. A run that crashes meanwhile leaves it where no later run
    // looks (stale temporaries are removed by evict()), so a poisoned entry costs one run, not
    // every run. Another run meanwhile finds no entry: a miss.
    std::optional<CacheEntry> borrow(const Sha256Digest& key, std::string& aside) const;
    void give_back(const Sha256Digest& key, const std::string& aside) const;
    // Removes the borrowed entry for good (the consumer refused it).
    void discard(const std::string& aside) const;
    // Removes the entry for `key` when it is ours.
    void remove(const Sha256Digest& key) const;
    // Writes the entry, then trims the folder to the size limit.
    void store(const Sha256Digest& key, const std::array<std::uint32_t, 2>& detail, const unsigned char* payload,
               std::size_t size) const;
    // Removes our stale temporary files, then our least recently used entries until the entries
    // take at most the size limit.
    void evict() const;

private:
    std::string root_, subfolder_;
    CacheEntryKind kind_;
    std::uint64_t size_limit_;
};

}  // namespace clr
