#include "scripts/forest/noise.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>

namespace forest {

std::uint32_t hash3(std::int32_t x, std::int32_t y, std::int32_t z, std::uint32_t seed) {
    std::uint32_t h = seed * 0x9E3779B1u;
    for (std::uint32_t part : {static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y),
                               static_cast<std::uint32_t>(z)}) {
        h ^= part + 0x7F4A7C15u + (h << 6) + (h >> 2);
        h *= 0x85EBCA6Bu;
        h ^= h >> 13;
    }
    h *= 0xC2B2AE35u;
    return h ^ (h >> 16);
}

double hash_unit(std::int32_t x, std::int32_t y, std::int32_t z, std::uint32_t seed) {
    return hash3(x, y, z, seed) * (1.0 / 4294967296.0);
}

namespace {

double smooth(double t) { return t * t * (3 - 2 * t); }
double mix(double a, double b, double t) { return a + (b - a) * t; }

}  // namespace

double value_noise(double x, double y, double z, std::uint32_t seed) {
    const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    const auto ix = static_cast<std::int32_t>(fx), iy = static_cast<std::int32_t>(fy), iz = static_cast<std::int32_t>(fz);
    const double tx = smooth(x - fx), ty = smooth(y - fy), tz = smooth(z - fz);
    auto corner = [&](int dx, int dy, int dz) { return hash_unit(ix + dx, iy + dy, iz + dz, seed); };
    const double near = mix(mix(corner(0, 0, 0), corner(1, 0, 0), tx), mix(corner(0, 1, 0), corner(1, 1, 0), tx), ty);
    const double far = mix(mix(corner(0, 0, 1), corner(1, 0, 1), tx), mix(corner(0, 1, 1), corner(1, 1, 1), tx), ty);
    return mix(near, far, tz);
}

double value_noise_2d(double x, double y, std::uint32_t seed) {
    const double fx = std::floor(x), fy = std::floor(y);
    const auto ix = static_cast<std::int32_t>(fx), iy = static_cast<std::int32_t>(fy);
    const double tx = smooth(x - fx), ty = smooth(y - fy);
    auto corner = [&](int dx, int dy) { return hash_unit(ix + dx, iy + dy, 0, seed); };
    return mix(mix(corner(0, 0), corner(1, 0), tx), mix(corner(0, 1), corner(1, 1), tx), ty);
}

// Octaves of `layer(scale, octave_seed)`, each twice the frequency and half the weight of the
// one before, normalised to the range of one layer.
template <typename Layer>
double octave_sum(int octaves, std::uint32_t seed, Layer layer) {
    double sum = 0, weight = 0, amplitude = 1, scale = 1;
    for (int octave = 0; octave < octaves; ++octave) {
        sum += amplitude * layer(scale, seed + 101u * octave);
        weight += amplitude;
        amplitude *= 0.5;
        scale *= 2.0;
    }
    return sum / weight;
}

double fractal_noise(double x, double y, double z, int octaves, std::uint32_t seed) {
    return octave_sum(octaves, seed, [&](double scale, std::uint32_t octave_seed) {
        return value_noise(x * scale, y * scale, z * scale, octave_seed);
    });
}

double fractal_noise_2d(double x, double y, int octaves, std::uint32_t seed) {
    return octave_sum(octaves, seed, [&](double scale, std::uint32_t octave_seed) {
        return value_noise_2d(x * scale, y * scale, octave_seed);
    });
}

double ridged_noise(double x, double y, int octaves, std::uint32_t seed) {
    double sum = 0, total = 0, amplitude = 1, weight = 1;
    for (int octave = 0; octave < octaves; ++octave) {
        const double crest = 1 - std::abs(2 * value_noise_2d(x, y, seed + 101u * octave) - 1);
        const double layer = crest * crest * weight;
        weight = std::clamp(2 * layer, 0.0, 1.0);
        sum += amplitude * layer;
        total += amplitude;
        amplitude *= 0.5;
        // Twice as fine, turned by about 37 degrees and shifted off the last layer's lattice.
        const double turned_x = 2 * (0.8 * x - 0.6 * y), turned_y = 2 * (0.6 * x + 0.8 * y);
        x = turned_x + 17.3;
        y = turned_y - 9.1;
    }
    return sum / total;
}

double smoothstep(double edge0, double edge1, double x) {
    const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3 - 2 * t);
}

}  // namespace forest
