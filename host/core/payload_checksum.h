// The checksum of a cache entry's payload (core/cache_entry.h): XXH3's 128-bit hash, from
// Debian's libxxhash. It guards against damage (a flipped bit, a truncated or interleaved
// write), where any 128-bit hash misses one damaged entry in 2^128; it is not what keeps an
// entry from being forged: the keys are SHA-256 (core/sha256.h), and anyone who could plant a
// payload in the private cache folder could write its checksum too, whatever the hash. On a
// warm start SHA-256 over the decoded images was a tenth of the process's time; XXH3 reads
// them at memory speed (docs/benchmarks.md, Against POV-Ray).
#pragma once

#include <array>
#include <cstddef>
#include <memory>

namespace clr {

using PayloadChecksum = std::array<unsigned char, 16>;  // XXH3-128, canonical (big-endian) form

// Incremental, so that a payload is checked while it is read, a block at a time in cache.
class PayloadChecksummer {
public:
    PayloadChecksummer();
    ~PayloadChecksummer();
    PayloadChecksummer(const PayloadChecksummer&) = delete;
    PayloadChecksummer& operator=(const PayloadChecksummer&) = delete;

    void add(const void* data, std::size_t size);
    PayloadChecksum finish() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

PayloadChecksum payload_checksum(const void* data, std::size_t size);

}  // namespace clr
