// The sRGB transfer function (IEC 61966-2-1): display values, which are what a scene's colours,
// the renderer's mean colours and the PNG's bytes / 255 are, turned back into the linear light
// values an EXR holds (docs/command-line.md, HDR and alpha outputs) and a linear viewer such as
// tev is sent (--display-server), so both show the picture an sRGB-aware viewer shows of the PNG.
#pragma once

#include <cstdint>

namespace clr {

// c / 12.92 for |c| <= 0.04045, else ((|c| + 0.055) / 1.055)^2.4 with c's sign: the standard's
// curve, continued beyond 1 (a colour brighter than the display's white stays brighter) and
// mirrored for negative values, as scRGB extends it. NaN stays NaN.
double srgb_to_linear(double display);

// The linear value, 0..1, of an sRGB-encoded byte: srgb_to_linear(byte / 255), from a table.
float srgb_byte_to_linear(std::uint8_t byte);

}  // namespace clr
