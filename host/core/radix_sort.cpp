#include "core/radix_sort.h"

#include <algorithm>
#include <utility>

namespace clr {

void radix_sort(std::vector<std::uint64_t>& keys, int ordered_bits) {
    RadixSortScratch scratch;
    radix_sort(keys, ordered_bits, scratch);
}

void radix_sort(std::vector<std::uint64_t>& keys, int ordered_bits, RadixSortScratch& scratch) {
    constexpr int kDigitBits = 16;
    constexpr std::size_t kBuckets = std::size_t{1} << kDigitBits;
    // Each pass clears and sums its 65,536 buckets: about 50 us a call for any count of keys,
    // where std::sort orders a few thousand keys faster (a still course frame sorts five).
    constexpr std::size_t kRadixFrom = 4096;
    if (keys.size() < kRadixFrom) {
        std::sort(keys.begin(), keys.end());
        return;
    }
    scratch.keys.resize(keys.size());  // every key written before read
    std::vector<std::uint32_t>& starts = scratch.starts;
    starts.resize(kBuckets);
    for (int shift = ordered_bits; shift < 64; shift += kDigitBits) {
        auto digit = [shift](std::uint64_t key) { return static_cast<std::size_t>(key >> shift) & (kBuckets - 1); };
        std::fill(starts.begin(), starts.end(), 0);
        for (std::uint64_t key : keys) ++starts[digit(key)];
        if (starts[digit(keys.front())] == keys.size()) continue;  // one digit for all: already in order
        std::uint32_t total = 0;
        for (std::uint32_t& start : starts) total += std::exchange(start, total);
        for (std::uint64_t key : keys) scratch.keys[starts[digit(key)]++] = key;
        keys.swap(scratch.keys);
    }
}

}  // namespace clr
