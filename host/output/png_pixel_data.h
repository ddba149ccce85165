// The pixels of a PNG as its IDAT chunks carry them: a zlib stream of the filtered rows.
// Compressed by ISA-L's igzip rather than by libpng's zlib, which took most of a frame's
// writing time (docs/benchmarks.md, Figures behind design choices).
#pragma once

#include <cstdint>
#include <vector>

#include "core/image.h"

namespace clr {

// The zlib stream of `image`'s rows, each with the Up filter (its bytes minus the bytes above
// it, which turns smooth gradients and flat areas into runs of zeros), RGB or, for
// image.write_alpha, RGBA. The same image always gives the same bytes (with the same ISA-L).
// Throws std::bad_alloc when memory runs out, std::runtime_error if the compressor fails (it
// refuses settings, never data) and std::length_error for rows beyond its 4 GiB input.
std::vector<std::uint8_t> png_pixel_data(const Image& image);

}  // namespace clr
