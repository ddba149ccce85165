// The documented way from an EXR value back to the PNG's byte (docs/command-line.md, HDR and
// alpha outputs), written from IEC 61966-2-1 rather than from clrender's code, in whatever
// floating-point type a user might compute it: float, double or long double.
#pragma once

#include <cmath>
#include <cstdint>

namespace clr::testing {

// Linear light to a display value: 12.92 v up to 0.0031308, else 1.055 v^(1/2.4) - 0.055;
// mirrored below 0. Every step in T.
template <typename T>
T srgb_encode(T v) {
    if (v < T(0)) return -srgb_encode(-v);
    if (v <= T(0.0031308)) return T(12.92) * v;
    return T(1.055) * std::pow(v, T(1) / T(2.4)) - T(0.055);
}

// floor(clamp(srgb_encode(v), 0, 1) * 255 + 0.5), every step in T; NaN gives 0.
template <typename T>
std::uint8_t png_byte_of(T v) {
    if (std::isnan(v)) return 0;
    T e = srgb_encode(v);
    e = e < T(0) ? T(0) : (e > T(1) ? T(1) : e);
    return static_cast<std::uint8_t>(std::floor(e * T(255) + T(0.5)));
}

}  // namespace clr::testing
