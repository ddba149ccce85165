// OpenEXR output (docs/command-line.md, HDR and alpha outputs): a frame's colours in linear
// light, unclamped (output/exr_values.h), as 32-bit float channels R, G, B, and A with --alpha,
// with sRGB's chromaticities.
#pragma once

#include <string>
#include <vector>

#include "core/image.h"

namespace clr {

// The whole EXR file in memory, so that it reaches the disk through AtomicFile like every
// other output. Throws OutputError naming `path` when the image has no float colours (or no
// display bytes to keep to) or the encoder fails.
std::vector<char> encode_exr(const std::string& path, const Image& image);

}  // namespace clr
