// radix_sort() orders 64-bit keys as std::sort does, whichever of their digits vary.
#include "core/radix_sort.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace clr {
namespace {

void expect_sorted_as_std_sort(std::vector<std::uint64_t> keys) {
    std::vector<std::uint64_t> expected = keys;
    std::sort(expected.begin(), expected.end());
    radix_sort(keys);
    EXPECT_EQ(keys, expected);
}

TEST(RadixSort, OrdersRandomKeysAsStdSort) {
    std::mt19937_64 random(5);
    std::vector<std::uint64_t> keys(20000);
    for (std::uint64_t& key : keys) key = random();
    expect_sorted_as_std_sort(keys);
}

TEST(RadixSort, OrdersFewKeysAsStdSortOnBothSidesOfTheRadixThreshold) {
    std::mt19937_64 random(11);
    for (std::size_t count : {2u, 5u, 4095u, 4096u, 4097u}) {
        std::vector<std::uint64_t> keys(count);
        for (std::uint64_t& key : keys) key = random() >> (count % 3 * 20);
        expect_sorted_as_std_sort(keys);
    }
}

TEST(RadixSort, OrdersKeysThatShareDigitsAndRepeat) {
    // As the screen tiles make them: a float's bits above, a small index below; many equal
    // distances, and digits that no key varies (those passes are skipped).
    std::mt19937 random(9);
    std::vector<std::uint64_t> keys;
    for (std::uint32_t i = 0; i < 5000; ++i) keys.push_back(std::uint64_t{0x41200000u + random() % 7} << 32 | (i * 7919u) % 5000u);
    keys.push_back(0);
    keys.push_back(~std::uint64_t{0});
    keys.push_back(keys[17]);
    expect_sorted_as_std_sort(keys);
    expect_sorted_as_std_sort({});
    expect_sorted_as_std_sort({3});
    expect_sorted_as_std_sort({std::uint64_t{1} << 48, 1});
}

// Keys whose low 32 bits already ascend (a float's bits above, each key's place below, as the
// screen tiles make them): sorting only the bits above gives std::sort's order, on both
// sides of the radix threshold.
TEST(RadixSort, KeysOrderedBelowABitSortAsStdSortWithoutPassingOverThem) {
    std::mt19937 random(13);
    for (std::uint32_t count : {3u, 4095u, 4096u, 70000u}) {
        std::vector<std::uint64_t> keys;
        for (std::uint32_t i = 0; i < count; ++i)
            keys.push_back(std::uint64_t{0x40000000u + random() % (count / 3 + 1) * 977u} << 32 | i * 3u);
        std::vector<std::uint64_t> expected = keys;
        std::sort(expected.begin(), expected.end());
        radix_sort(keys, 32);
        EXPECT_EQ(keys, expected) << count << " keys";
    }
}

}  // namespace
}  // namespace clr
