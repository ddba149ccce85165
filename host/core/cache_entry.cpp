#include "core/cache_entry.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "core/huge_pages.h"
#include "core/payload_checksum.h"

namespace clr {
namespace {

// Numbers in the host's byte order: a cache folder is not shared between machines, and a
// foreign order fails the version check.
struct EntryHeader {
    char magic[8];
    std::uint32_t layout_version;  // of this header, shared by every cache
    std::uint32_t kind_version;    // CacheEntryKind::version
    std::array<std::uint32_t, 2> detail;
    std::uint64_t payload_size;
    Sha256Digest key;
    PayloadChecksum payload_checksum;
    unsigned char reserved[16];  // zero
    Sha256Digest header_digest;  // of every byte above
};
static_assert(sizeof(EntryHeader) == kCacheEntryHeaderBytes, "the header is written and read as raw bytes");

// 2: the payload's checksum is XXH3-128 (core/payload_checksum.h), no longer SHA-256.
constexpr std::uint32_t kLayoutVersion = 2;

// The payload is read and checksummed a block at a time, so that each block is checked while
// it is still in the CPU's cache.
constexpr std::size_t kReadBlock = std::size_t(1) << 20;

Sha256Digest digest_of_header(const EntryHeader& header) {
    return sha256(&header, offsetof(EntryHeader, header_digest));
}

// The header's own checks, before any payload byte is read or allocated.
bool header_fits(const EntryHeader& header, const CacheEntryKind& kind, const Sha256Digest& key, std::uint64_t file_size) {
    return digest_of_header(header) == header.header_digest && header.layout_version == kLayoutVersion &&
           header.kind_version == kind.version && header.key == key && header.payload_size <= kind.largest_payload &&
           file_size - sizeof header == header.payload_size;
}

}  // namespace

bool read_exactly(int descriptor, void* destination, std::size_t size) {
    auto* bytes = static_cast<unsigned char*>(destination);
    while (size > 0) {
        const ssize_t got = ::read(descriptor, bytes, size);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) return false;
        bytes += got;
        size -= static_cast<std::size_t>(got);
    }
    return true;
}

bool write_exactly(int descriptor, const void* source, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(source);
    while (size > 0) {
        const ssize_t put = ::write(descriptor, bytes, size);
        if (put < 0 && errno == EINTR) continue;
        if (put <= 0) return false;
        bytes += put;
        size -= static_cast<std::size_t>(put);
    }
    return true;
}

EntryCheck read_cache_entry(int descriptor, const CacheEntryKind& kind, const Sha256Digest& key, CacheEntry& entry) {
    if (!starts_with_magic(descriptor, kind, /*allow_short=*/false)) return EntryCheck::Foreign;
    struct stat info;
    EntryHeader header;
    if (::lseek(descriptor, 0, SEEK_SET) != 0 || ::fstat(descriptor, &info) != 0 ||
        static_cast<std::uint64_t>(info.st_size) < sizeof header || !read_exactly(descriptor, &header, sizeof header) ||
        !header_fits(header, kind, key, static_cast<std::uint64_t>(info.st_size)))
        return EntryCheck::Bad;
    entry.detail = header.detail;
    resize_with_huge_pages(entry.payload, header.payload_size);
    PayloadChecksummer checksum;
    for (std::size_t done = 0; done < entry.payload.size();) {
        const std::size_t block = std::min(kReadBlock, entry.payload.size() - done);
        if (!read_exactly(descriptor, entry.payload.data() + done, block)) {
            entry.payload = {};
            return EntryCheck::Bad;
        }
        checksum.add(entry.payload.data() + done, block);
        done += block;
    }
    if (checksum.finish() != header.payload_checksum) {
        entry.payload = {};
        return EntryCheck::Bad;
    }
    return EntryCheck::Good;
}

bool write_cache_entry(int descriptor, const CacheEntryKind& kind, const Sha256Digest& key,
                       const std::array<std::uint32_t, 2>& detail, const unsigned char* payload, std::size_t size) {
    EntryHeader header{};
    std::memcpy(header.magic, kind.magic.data(), sizeof header.magic);
    header.layout_version = kLayoutVersion;
    header.kind_version = kind.version;
    header.detail = detail;
    header.payload_size = size;
    header.key = key;
    header.payload_checksum = payload_checksum(payload, size);
    header.header_digest = digest_of_header(header);
    return write_exactly(descriptor, &header, sizeof header) && write_exactly(descriptor, payload, size);
}

bool starts_with_magic(int descriptor, const CacheEntryKind& kind, bool allow_short) {
    char start[sizeof kind.magic];
    std::size_t got = 0;
    while (got < sizeof start) {
        const ssize_t read = ::pread(descriptor, start + got, sizeof start - got, static_cast<off_t>(got));
        if (read < 0 && errno == EINTR) continue;
        if (read <= 0) break;
        got += static_cast<std::size_t>(read);
    }
    if (got < sizeof start && !allow_short) return false;
    return std::memcmp(start, kind.magic.data(), got) == 0;
}

}  // namespace clr
