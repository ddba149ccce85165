// SHA-256 through OpenSSL's libcrypto, for the keys and checksums of clrender's caches: a key
// that nobody can forge (a 64-bit hash can be matched to another file in microseconds, and the
// cache would then show the other file's picture) and a checksum that catches any damaged byte.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace clr {

using Sha256Digest = std::array<unsigned char, 32>;

// Incremental hashing. Each add_field() is prefixed with its length, so that the fields of a
// key cannot slide into each other ("ab" + "c" and "a" + "bc" give different digests).
// Throws std::runtime_error in the unlikely case that libcrypto refuses (e.g. a broken
// FIPS setup); the caches take that as "no caching".
class Sha256 {
public:
    Sha256();
    ~Sha256();
    Sha256(const Sha256&) = delete;
    Sha256& operator=(const Sha256&) = delete;

    Sha256& add(const void* data, std::size_t size);
    Sha256& add_field(const void* data, std::size_t size);
    Sha256& add_field(const std::string& text) { return add_field(text.data(), text.size()); }
    Sha256& add_number(std::uint64_t number);  // as a field of 8 little-endian bytes
    Sha256Digest finish();

private:
    struct Context;
    std::unique_ptr<Context> context_;
};

Sha256Digest sha256(const void* data, std::size_t size);

// 64 lower-case hex digits.
std::string to_hex(const Sha256Digest& digest);

}  // namespace clr
