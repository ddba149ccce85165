// The size limits a scene, an image file and the command line share, defined once so that the
// loader, the image decoders, the options and the messages cannot drift apart.
#pragma once

#include <string>

namespace clr {

// Largest side of a rendered image, and largest image in pixels, so that a frame (RGBA, 4 bytes
// a pixel, plus a ray and a hit record per pixel for the stage kernels) stays well inside
// memory. An image file read for a billboard is held to the same pixel count.
constexpr int kMaxImageSide = 16384;
constexpr int kMaxSquareImageSide = 8192;
constexpr long long kMaxImagePixels = static_cast<long long>(kMaxSquareImageSide) * kMaxSquareImageSide;

// The pixel limit as a square, for messages: "8192 x 8192".
inline std::string max_square_image_text() {
    return std::to_string(kMaxSquareImageSide) + " x " + std::to_string(kMaxSquareImageSide);
}

// Most samples per pixel (anti-aliasing) a scene or --spp may ask for.
constexpr int kMaxSamplesPerPixel = 4096;

}  // namespace clr
