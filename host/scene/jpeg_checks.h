// Checks of a JPEG's frame header made before libjpeg-turbo decodes it (scene/jpeg_decoder.h),
// so that a valid file of a kind clrender does not decode is named as such, not as corrupt.
#pragma once

#include <optional>
#include <vector>

namespace clr {

// A JPEG's frame header (SOFn): the coding process, sample precision, size and components.
struct JpegFrame {
    unsigned marker = 0;  // 0xC0 baseline, 0xC1 extended, 0xC2 progressive, 0xC3 lossless, ...
    unsigned precision = 0;  // bits a sample
    unsigned height = 0, width = 0;
    unsigned components = 0;
    // The components' samples a pixel: 3 for 4:4:4 colour, 1.5 for 4:2:0, 1 for grey.
    double samples_per_pixel = 0;
};

// The frame header, found by following the segments from the start of the image; nullopt when
// the segments cannot be followed to one (the decoder then says what is wrong).
std::optional<JpegFrame> find_jpeg_frame(const std::vector<unsigned char>& bytes);

// Refuses a JPEG that is valid but of a kind libjpeg-turbo 2.1 (Debian 12) does not decode to
// colour, naming the kind: lossless or hierarchical (SOF3, SOF5-7, SOF11, SOF13-15), samples of
// other than 8 bits, or other than 1 (grey), 3 (colour) or 4 (CMYK) components. Arithmetic-coded
// baseline and progressive JPEG (SOF9, SOF10) are decoded.
void check_jpeg_frame_is_supported(const JpegFrame& frame);

}  // namespace clr
