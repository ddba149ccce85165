// The display bytes of linear colours, by the kernels' rule (color_to_byte() in
// kernels/common/math.cl; docs/scene-format.md, Conventions: Colour), computed in float as the
// kernels compute them, so that a frame rendered in the float output mode gives exactly the
// bytes of the same frame rendered without.
#pragma once

#include <cstdint>

#include "core/image.h"

namespace clr {

// round(clamp(c, 0, 1) * 255), halves rounded up; NaN shows as 0 (as the reference shows it).
std::uint8_t display_byte(float channel);

// Sets image.rgba from image.linear: RGB by display_byte(), alpha 255.
void fill_display_bytes(Image& image);

}  // namespace clr
