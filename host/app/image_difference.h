// How a rendered frame and an image of the same size differ, pixel by pixel, in R, G and B
// (docs/command-line.md, Comparing with an image): how many pixels differ by more than a
// tolerance, and which differ most. Alpha is not compared: a rendered frame is opaque.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/image.h"

namespace clr {

struct PixelDifference {
    int x = 0;  // column from the left, 0-based
    int y = 0;  // row from the top, 0-based
    std::array<std::uint8_t, 3> rendered{};
    std::array<std::uint8_t, 3> image{};
    int difference = 0;  // the largest of the three channels' absolute differences, 0..255
};

struct ImageDifference {
    int width = 0, height = 0;
    int tolerance = 0;               // in 1/255 steps: a channel may differ by this much
    std::uint64_t differing = 0;     // pixels with a channel that differs by more than the tolerance
    int largest = 0;                 // the largest channel difference of any pixel, 0..255
    // The pixels that differ most, among those beyond the tolerance: the largest difference
    // first, ties in reading order (row, then column).
    std::vector<PixelDifference> largest_pixels;

    std::uint64_t pixels() const { return static_cast<std::uint64_t>(width) * height; }
    double differing_share() const { return pixels() ? static_cast<double>(differing) / pixels() : 0.0; }
};

// The largest of the three channels' absolute differences of pixel (x, y).
int channel_difference(const Image& rendered, const Image& image, int x, int y);

// Compares R, G and B of two images of the same size (std::invalid_argument otherwise);
// `tolerance` is 0..255 (std::invalid_argument otherwise); lists at most `listed` pixels.
ImageDifference difference_of(const Image& rendered, const Image& image, int tolerance, std::size_t listed = 10);

}  // namespace clr
