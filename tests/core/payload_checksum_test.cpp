// The checksum of cache entry payloads: XXH3-128 as xxHash defines it, the same fed in blocks.
#include "core/payload_checksum.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace clr {
namespace {

std::string hex(const PayloadChecksum& checksum) {
    std::string text;
    char digits[3];
    for (unsigned char byte : checksum) {
        std::snprintf(digits, sizeof digits, "%02x", byte);
        text += digits;
    }
    return text;
}

// xxHash's own sanity value for XXH3-128 of no bytes (seed 0), high half first.
TEST(PayloadChecksum, IsXxh3With128BitsInCanonicalOrder) {
    EXPECT_EQ(hex(payload_checksum(nullptr, 0)), "99aa06d3014798d86001c324468d497f");
}

TEST(PayloadChecksum, BlockByBlockIsTheSameAsAllAtOnce) {
    std::vector<unsigned char> bytes(3 * 1000 * 1000 + 17);
    for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<unsigned char>(i * 2654435761u >> 13);
    PayloadChecksummer blocks;
    for (std::size_t done = 0; done < bytes.size(); done += 1 << 20)
        blocks.add(bytes.data() + done, std::min<std::size_t>(1 << 20, bytes.size() - done));
    EXPECT_EQ(blocks.finish(), payload_checksum(bytes.data(), bytes.size()));
}

TEST(PayloadChecksum, OneFlippedBitAnywhereChangesIt) {
    std::vector<unsigned char> bytes(5 << 20, 0x5a);
    const PayloadChecksum whole = payload_checksum(bytes.data(), bytes.size());
    for (std::size_t at : {std::size_t(0), bytes.size() / 2, bytes.size() - 1}) {
        bytes[at] ^= 1;
        EXPECT_NE(payload_checksum(bytes.data(), bytes.size()), whole) << "bit flipped at " << at;
        bytes[at] ^= 1;
    }
    EXPECT_NE(payload_checksum(bytes.data(), bytes.size() - 1), whole) << "one byte short";
}

}  // namespace
}  // namespace clr
