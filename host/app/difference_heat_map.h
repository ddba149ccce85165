// A picture of where a rendered frame and an image differ (docs/command-line.md, Comparing
// with an image): each pixel whose largest channel difference d (in 1/255 steps) is beyond
// the tolerance gets a colour of a logarithmic scale, blue at d = 1, cyan near 4, green near
// 16, yellow near 64 and red at 255; every other pixel shows the rendered frame in dark grey
// (its luminance divided by 4, at most 63), so the differences stand out in their context.
#pragma once

#include <array>
#include <cstdint>

#include "core/image.h"

namespace clr {

// The colour of a difference d, 1..255 (clamped into that range).
std::array<std::uint8_t, 3> heat_colour(int difference);

// The grey that a pixel within the tolerance shows: the rendered colour's luminance
// (Rec. 709 weights, on the bytes) divided by 4, rounded.
std::uint8_t context_grey(std::uint8_t r, std::uint8_t g, std::uint8_t b);

// The heat map of two images of the same size (std::invalid_argument otherwise), opaque RGB.
Image difference_heat_map(const Image& rendered, const Image& image, int tolerance);

}  // namespace clr
