// The sRGB transfer function (IEC 61966-2-1): clrender's PNG bytes are marked as sRGB, so a
// viewer that takes linear values (tev) is given each byte decoded by it, and shows the
// picture an sRGB-aware viewer shows of the PNG.
#pragma once

#include <cstdint>

namespace clr {

// The linear value, 0..1, of an sRGB-encoded byte: b/255 / 12.92 up to 0.04045, else
// ((b/255 + 0.055) / 1.055)^2.4.
float srgb_byte_to_linear(std::uint8_t byte);

}  // namespace clr
