// PNG files that hold only a header: enough for a reader to learn the size an image claims,
// without the test having to make (or decode) the pixels.
#pragma once

#include <cstdint>
#include <string>

namespace clr::testing {

// The signature and IHDR chunk of an RGBA PNG of `width` x `height` at `bit_depth` (8 or 16),
// with a correct CRC, and no pixel data: decoding it fails as corrupt.
std::string png_header_only(std::uint32_t width, std::uint32_t height, int bit_depth);

}  // namespace clr::testing
