// Decoded images kept across runs. Decoding the large PNGs of a course scene is most of the time
// a warm start takes; reading back and checking the decoded RGBA is a fraction of that
// (docs/benchmarks.md, Figures behind design choices). Entries live in images/ under the cache folder
// (core/cache_folder.h), one file per image (core/cache_entry_folder.h), named by the SHA-256 of
// the source file's whole content and of everything else that decides the decoded pixels, so an
// edited image is a new key and its old entry is never used, and no file can be forged to look
// like another. An entry that is missing or fails a check (core/cache_entry.h) is a miss, never
// an error; writing is best effort. Only images of at least kSmallestStoredBytes decoded are
// stored, and the folder is kept under a size limit by removing the least recently used entries
// (a hit refreshes its entry's modification time).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/cache_entry_folder.h"
#include "core/image.h"
#include "core/sha256.h"

namespace clr {

class ImageCache {
public:
    // Smaller images decode about as fast as an entry is looked up and read: not worth the disk.
    static constexpr std::size_t kSmallestStoredBytes = 1u << 20;
    static constexpr std::uint64_t kDefaultSizeLimit = std::uint64_t(1) << 30;
    // Part of every key and header: a change of the entry layout or of what decoding produces
    // (e.g. rounding of 16-bit samples) or of which files decode at all (3: JPEG scans using
    // undefined Huffman tables are refused; 4: JPEG decoded by libjpeg-turbo, whose pixels differ
    // from stb's by a few steps) must bump it, so that old entries stop matching.
    static constexpr std::uint32_t kFormatVersion = 4;

    // The SHA-256 of the source file's bytes and of what decodes them.
    using Key = Sha256Digest;

    // images/ under cache_folder_from_environment(); disabled when that is "".
    static ImageCache from_environment();

    // Entries go in `cache_folder`/images; "" disables the cache. `size_limit`: most bytes of
    // entries kept there.
    explicit ImageCache(std::string cache_folder, std::uint64_t size_limit = kDefaultSizeLimit);
    bool enabled() const { return entries_.enabled(); }
    std::string folder() const { return entries_.folder(); }

    static Key key(const std::vector<unsigned char>& file_bytes);
    // Does the one-time work of the first key now, on this thread: the decoder's identity asks
    // the dynamic loader, and libcrypto initialises itself, both of which wait for a dlopen
    // under way on another thread (the OpenCL driver's, tens of milliseconds). Never throws:
    // a failure here is met again, and handled, by key().
    static void prepare_keys() noexcept;
    // The entry's file for `key`.
    std::string path(const Key& key) const { return entries_.path(key); }

    // The image stored for `key`, its path set to `source_path`; nullptr on a miss. A hit
    // refreshes the entry's modification time, which is what eviction goes by.
    std::shared_ptr<const Image> load(const Key& key, const std::string& source_path) const;
    // Stores `image` when it is large enough, then trims the folder to the size limit. Best
    // effort: a folder that cannot be written just leaves the cache as it was.
    void store(const Key& key, const Image& image) const;

private:
    CacheEntryFolder entries_;
};

// load_image(path) through `cache`: the same image, and the same ImageError for a file that
// cannot be read or decoded (failures are never stored, so they are reported every time).
std::shared_ptr<const Image> load_image_through_cache(const std::string& path, const ImageCache& cache);

}  // namespace clr
