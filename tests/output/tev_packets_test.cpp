// tev's IPC packets as clrender writes them (host/output/tev_packets.h), byte by byte against
// tev's protocol: the length counts its own 4 bytes, integers little-endian, strings end with
// a 0 byte, UpdateImage (version 3) carries an offset and a stride per channel.
#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>

#include "output/tev_packets.h"

namespace clr {
namespace {

std::vector<std::uint8_t> bytes(std::initializer_list<int> values) {
    std::vector<std::uint8_t> result;
    for (int value : values) result.push_back(static_cast<std::uint8_t>(value));
    return result;
}

TEST(TevPackets, CreateImageByteForByte) {
    const TevPacket packet = tev_create_image("ab", 3, 258, {"R", "G", "B"});
    const std::vector<std::uint8_t> expected = bytes({
        27, 0, 0, 0,        // length: 4 (itself) + 1 + 1 + 3 + 4 + 4 + 4 + 6 = 27
        4,                  // CreateImage
        1,                  // grab focus
        'a', 'b', 0,        // name
        3, 0, 0, 0,         // width
        2, 1, 0, 0,         // height 258
        3, 0, 0, 0,         // channels
        'R', 0, 'G', 0, 'B', 0,
    });
    EXPECT_EQ(packet, expected);
}

TEST(TevPackets, UpdateImageByteForByte) {
    const float one = 1.0f, half = 0.5f;
    std::uint8_t one_bytes[4], half_bytes[4];
    std::uint32_t bits = 0;
    std::memcpy(&bits, &one, 4);
    for (int i = 0; i < 4; ++i) one_bytes[i] = static_cast<std::uint8_t>(bits >> (8 * i));
    std::memcpy(&bits, &half, 4);
    for (int i = 0; i < 4; ++i) half_bytes[i] = static_cast<std::uint8_t>(bits >> (8 * i));

    const TevPacket packet = tev_update_image("x", {"R", "G"}, 5, 6, 1, 1, {1.0f, 0.5f});
    std::vector<std::uint8_t> expected = bytes({
        0, 0, 0, 0,            // length, checked below
        6,                     // UpdateImage, version 3
        0,                     // no focus
        'x', 0,
        2, 0, 0, 0,            // channels
        'R', 0, 'G', 0,
        5, 0, 0, 0, 6, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0,  // x, y, width, height
        0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0,  // offsets 0, 1 (int64)
        2, 0, 0, 0, 0, 0, 0, 0, 2, 0, 0, 0, 0, 0, 0, 0,  // strides 2, 2 (int64)
    });
    expected.insert(expected.end(), one_bytes, one_bytes + 4);
    expected.insert(expected.end(), half_bytes, half_bytes + 4);
    expected[0] = static_cast<std::uint8_t>(expected.size());
    EXPECT_EQ(packet, expected);
}

TEST(TevPackets, CloseImage) {
    EXPECT_EQ(tev_close_image("im"), bytes({8, 0, 0, 0, 2, 'i', 'm', 0}));
}

TEST(TevPackets, RefusesWhatTevWouldMisread) {
    EXPECT_THROW(tev_update_image("x", {"R", "G", "B"}, 0, 0, 2, 2, std::vector<float>(11)), std::invalid_argument);
    EXPECT_THROW(tev_update_image("x", {}, 0, 0, 1, 1, {}), std::invalid_argument);
    EXPECT_THROW(tev_create_image(std::string("a\0b", 3), 1, 1, {"R"}), std::invalid_argument);
}

}  // namespace
}  // namespace clr
