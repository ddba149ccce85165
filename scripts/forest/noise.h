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

// The same over a plane, at half the cost: for textures that need no third coordinate.
double value_noise_2d(double x, double y, std::uint32_t seed);

// Fractal sum of `octaves` layers of value noise, each twice as fine and half as strong;
// in [0, 1).
double fractal_noise(double x, double y, double z, int octaves, std::uint32_t seed);

// fractal_noise over a plane.
double fractal_noise_2d(double x, double y, int octaves, std::uint32_t seed);

// Ridged fractal noise over a plane, in [0, 1]: sharp crests along the middle contour of each
// layer, where the finer layers are also strongest, so that peaks get rugged and valleys stay
// smooth. Each layer is turned against the last, so no ridge follows the lattice.
double ridged_noise(double x, double y, int octaves, std::uint32_t seed);

// 0 below edge0, 1 above edge1, a smooth S-curve between: turns noise into soft-edged patches.
double smoothstep(double edge0, double edge1, double x);

}  // namespace forest
