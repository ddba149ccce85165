// A small, fully specified pseudo-random generator (SplitMix64). The standard library's
// distributions may differ between implementations, so every draw of the forest goes through
// this class: the same seed gives the same forest on every machine.
#pragma once

#include <cstdint>

namespace forest {

class Random {
public:
    explicit Random(std::uint64_t seed) : state_(seed) {}

    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
        return z ^ (z >> 31);
    }

    // Uniform in [0, 1), from the top 53 bits (exact in a double).
    double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    double uniform(double low, double high) { return low + (high - low) * unit(); }
    // Uniform whole number in [0, count).
    int below(int count) { return static_cast<int>(unit() * count); }

private:
    std::uint64_t state_;
};

// A seed for one part of the forest (a tree kind, the ground...), so that changing how many
// draws one part makes does not shift the others.
inline std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t part) {
    return Random(seed * 0x100000001B3ULL + part).next();
}

}  // namespace forest
