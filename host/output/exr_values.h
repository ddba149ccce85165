// The values an EXR file holds for a frame (docs/command-line.md, HDR and alpha outputs): the
// renderer's colours are display values, as the scene's are and as the PNG's bytes / 255 are,
// so the EXR holds them in linear light (the sRGB transfer function undone), where a
// colour-managed viewer shows the same picture as the sRGB-tagged PNG.
//
// Every value is chosen so that the documented way back to the PNG's byte,
// floor(clamp(srgb_encode(v), 0, 1) * 255 + 0.5), gives that byte whatever precision it is
// computed in: a value whose display value lies within kRoundingMargin of a byte step's
// rounding threshold is moved that far to the PNG byte's side first. Without that, a value
// within a float's rounding of a threshold rounds to the other byte in float or in double.
#pragma once

#include <cstdint>
#include <vector>

#include "core/image.h"

namespace clr {

// In byte steps (1/255 of the display range): far more than float32's error in srgb_encode
// (about 1e-4 of a step) and small enough not to matter (4e-5 of the display range at most).
constexpr double kRoundingMargin = 0.01;

// The linear value stored for a channel whose display value is `display` and whose PNG byte is
// `byte` (display_byte(display), or the reference's byte of the same colour): `display` kept
// inside [byte - 0.5 + margin, byte + 0.5 - margin] / 255 (no lower bound for byte 0, no upper
// bound for 255: below 0 and above 1 stay as they are), then srgb_to_linear(). NaN stays NaN.
float exr_linear_value(float display, std::uint8_t byte);

// R, G, B, A per pixel from image.linear (display values, unclamped; with --alpha the colour of
// the samples that hit alone, as alpha_convention.h leaves it) and image.rgba (the PNG's bytes):
// without write_alpha, RGB = exr_linear_value() and A = 1; with it, premultiplied in linear
// light, RGB = a * exr_linear_value() (0 where a is 0) and A = a, the coverage.
std::vector<float> exr_values(const Image& image);

}  // namespace clr
