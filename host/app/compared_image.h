// The image that `clrender compare` compares a render with (docs/command-line.md, Comparing
// with an image): PNG, JPEG or PPM, checked to be of the render's size from its header before
// its pixels are decoded, so that a wrong or huge file costs no decoding.
#pragma once

#include <string>

#include "core/image.h"

namespace clr {

// Reads the image at `path`, which must be `width` x `height` pixels. A PNG of clrender's
// form (8-bit RGB or RGBA) is decoded with every chunk's checksum checked, so that a damaged
// file is refused rather than compared; other PNGs must end with their IEND chunk. Throws
// SceneError naming `path` (exit code 2): missing, unreadable, not an image, damaged, or of
// another size (both sizes named).
Image read_compared_image(const std::string& path, int width, int height);

}  // namespace clr
