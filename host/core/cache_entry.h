// One entry file of a clrender cache: a fixed 128-byte header, then the payload (decoded pixels,
// a program binary). Everything is checked before anything is used: the header carries its own
// SHA-256, the key it was stored for and the payload's checksum (core/payload_checksum.h), and
// its sizes must match the file's before anything is allocated. A damaged, truncated, foreign or misnamed entry therefore
// never reaches a caller.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/sha256.h"

namespace clr {

// What differs between the caches' entries.
struct CacheEntryKind {
    std::string extension;           // of entry files, without the dot: "rgba", "clbin"
    std::array<char, 8> magic;       // the first bytes of every entry of this cache
    std::uint32_t version;           // the cache's own format version: a change is a miss
    std::uint64_t largest_payload;   // a header claiming more is refused before allocating
};

struct CacheEntry {
    std::array<std::uint32_t, 2> detail{};  // two numbers of the cache's own (an image's size)
    std::vector<unsigned char> payload;
};

constexpr std::size_t kCacheEntryHeaderBytes = 128;

enum class EntryCheck {
    Good,     // verified, for this key
    Foreign,  // does not start with the kind's magic: not clrender's, never touched
    Bad,      // clrender's magic but fails a check (damaged, truncated, another key, old version)
};

// Reads the entry open at `descriptor` (at offset 0, a regular file) into `entry`.
EntryCheck read_cache_entry(int descriptor, const CacheEntryKind& kind, const Sha256Digest& key, CacheEntry& entry);

// Writes a whole entry to `descriptor`; false when any write fails (full disk, quota).
bool write_cache_entry(int descriptor, const CacheEntryKind& kind, const Sha256Digest& key,
                       const std::array<std::uint32_t, 2>& detail, const unsigned char* payload, std::size_t size);

// Whether the file open at `descriptor` begins with the kind's magic; with `allow_short`, a
// file shorter than the magic whose bytes are its start counts too (a write cut short).
bool starts_with_magic(int descriptor, const CacheEntryKind& kind, bool allow_short);

// read()/write() of exactly `size` bytes, retrying after signals and short transfers.
bool read_exactly(int descriptor, void* destination, std::size_t size);
bool write_exactly(int descriptor, const void* source, std::size_t size);

}  // namespace clr
