// Deterministic lattice noise for the hand-drawn textures: integer hashing, so that the same
// coordinates give the same value on every machine.
#pragma once

#include <cstdint>

namespace forest {

// A well-mixed 32-bit hash of three integers and a seed.
std::uint32_t hash3(std::int32_t x, std::int32_t y, std::int32_t z, std::uint32_t seed);

// The hash as a number in [0, 1).
double hash_unit(std::int32_t x, std::int32_t y, std::int32_t z, std::uint32_t seed);

// Smoothly interpolated value noise in [0, 1) with features about 1 unit apart.
double value_noise(double x, double y, double z, std::uint32_t seed);

// Fractal sum of `octaves` layers of value noise, each twice as fine and half as strong;
// in [0, 1).
double fractal_noise(double x, double y, double z, int octaves, std::uint32_t seed);

}  // namespace forest
