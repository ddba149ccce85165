// Decoded images kept across runs. Decoding the large PNGs of a course scene is most of the time
// a warm start takes (about 80-100 ms of it for three photos); reading back the decoded RGBA is a
// few milliseconds. Entries live in images/ under the cache folder (core/cache_folder.h), one
// file per image, named by a hash of the source file's whole content and its size, so an edited
// image is a new key and its old entry is never used. An entry that is missing, short, or has the
// wrong magic, version or key is a miss, never an error; writing is best effort. Only images of
// at least kSmallestStoredBytes decoded are stored, and the folder is kept under a size limit by
// removing the least recently used entries (a hit refreshes its entry's modification time).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace clr {

class ImageCache {
public:
    // Smaller images decode about as fast as an entry is looked up and read: not worth the disk.
    static constexpr std::size_t kSmallestStoredBytes = 1u << 20;
    static constexpr std::uint64_t kDefaultSizeLimit = std::uint64_t(1) << 30;
    // Part of every key and header: a change of the entry layout or of what decoding produces
    // (e.g. rounding of 16-bit samples) must bump it, so that old entries stop matching.
    static constexpr std::uint32_t kFormatVersion = 1;

    // The source file a decoded image came from, identified by its content.
    struct Key {
        std::uint64_t content_hash = 0;
        std::uint64_t byte_size = 0;
    };

    // images/ under cache_folder_from_environment(); disabled when that is "".
    static ImageCache from_environment();

    // `folder` "" disables the cache. `size_limit`: most bytes of entries kept in the folder.
    explicit ImageCache(std::string folder, std::uint64_t size_limit = kDefaultSizeLimit)
        : folder_(std::move(folder)), size_limit_(size_limit) {}
    bool enabled() const { return !folder_.empty(); }
    const std::string& folder() const { return folder_; }

    static Key key(const std::vector<unsigned char>& file_bytes);
    // The entry's file for `key`.
    std::string path(const Key& key) const;

    // The image stored for `key`, its path set to `source_path`; nullptr on a miss. A hit
    // refreshes the entry's modification time, which is what eviction goes by.
    std::shared_ptr<const Image> load(const Key& key, const std::string& source_path) const;
    // Stores `image` when it is large enough, then trims the folder to the size limit. Best
    // effort: a folder that cannot be written just leaves the cache as it was.
    void store(const Key& key, const Image& image) const;

private:
    void evict_least_recently_used() const;

    std::string folder_;
    std::uint64_t size_limit_;
};

// load_image(path) through `cache`: the same image, and the same ImageError for a file that
// cannot be read or decoded (failures are never stored, so they are reported every time).
std::shared_ptr<const Image> load_image_through_cache(const std::string& path, const ImageCache& cache);

}  // namespace clr
