// Rectangles of images for the crop tests: a crop must equal the same rectangle of the full frame.
#pragma once

#include "core/image.h"
#include "core/pixel_rect.h"

namespace clr::testing {

// The pixels of `rect` cut from `full`, as an image of the rectangle's size.
Image cut(const Image& full, const PixelRect& rect);

// Copies `part` (of the rectangle's size) into `whole` at `rect`.
void paste(Image& whole, const Image& part, const PixelRect& rect);

}  // namespace clr::testing
