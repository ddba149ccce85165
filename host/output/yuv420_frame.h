// Converts a frame to the Y'CbCr 4:2:0 that an MP4's H.264 stream holds, in clrender rather
// than in ffmpeg: the encoder then gets 1.5 bytes a pixel instead of 4 and does no colour
// conversion of its own (docs/animation.md, MP4 encoding).
#pragma once

#include <cstdint>
#include <vector>

#include "core/image.h"

namespace clr {

// The frame's size rounded up to even numbers: H.264 in 4:2:0 needs even dimensions.
int even_size(int size);

// The bytes of a yuv420p frame of width x height pixels padded to even_size() of both.
std::size_t yuv420_bytes(int width, int height);

// Writes `frame` into `yuv` (resized to yuv420_bytes()) as three planes, ffmpeg's yuv420p: Y'
// for every pixel, then Cb and Cr for every 2x2 block, the mean of its four pixels. BT.709
// matrix, limited ("TV") range (Y' 16-235, Cb and Cr 16-240), from 8-bit R'G'B' (the alpha
// byte is ignored):
//     Y' = 16  + 219/255 * (Kr R' + Kg G' + Kb B')
//     Cb = 128 + 224/255 * (B' - (Kr R' + Kg G' + Kb B')) / (2 (1 - Kb))
//     Cr = 128 + 224/255 * (R' - (Kr R' + Kg G' + Kb B')) / (2 (1 - Kr))
// with Kr = 0.2126, Kb = 0.0722, Kg = 1 - Kr - Kb (Cb and Cr of a block from the sums of its
// four pixels' R'G'B', divided by 4),
// rounded to the nearest integer, computed in 16-bit fixed point (within 1 of the exact
// value). An odd width or height gains a black column or row (R'G'B' 0), as a padded frame
// would. Integer arithmetic only: the same frame gives the same bytes on every machine.
void rgba_to_yuv420(const Image& frame, std::vector<std::uint8_t>& yuv);

}  // namespace clr
