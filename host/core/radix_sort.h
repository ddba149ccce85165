// Sorting many 64-bit keys in linear time: the screen tiles sort every visible object of
// every frame by distance, 100,000 spheres in one benchmark scene, where std::sort took
// 5-8 ms of a 40 ms frame and this takes about 1 ms (docs/benchmarks.md).
#pragma once

#include <cstdint>
#include <vector>

namespace clr {

// Sorts `keys` in ascending order (a least-significant-digit radix sort, 16 bits a pass;
// passes over digits that all keys share are skipped; fewer than 4,096 keys by std::sort).
// Keys whose lowest `ordered_bits` bits (a multiple of 16) already ascend in the order the
// keys come in, such as a key's index, need no pass over those bits: each pass keeps the
// order of equal digits, so keys equal above those bits stay in that order.
void radix_sort(std::vector<std::uint64_t>& keys, int ordered_bits = 0);

// The sort's working arrays, for a caller that sorts every frame: kept, they cost no page
// faults after the first (1 MB for 100,000 keys).
struct RadixSortScratch {
    std::vector<std::uint64_t> keys;
    std::vector<std::uint32_t> starts;
};
void radix_sort(std::vector<std::uint64_t>& keys, int ordered_bits, RadixSortScratch& scratch);

}  // namespace clr
