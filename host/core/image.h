// An 8-bit RGBA image: what a scene's pictures are decoded to, what a frame renders into and
// what the outputs write. Pixels only; reading image files is scene/image_loader's.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace clr {

// Rows from top to bottom, 4 bytes a texel. Images without alpha get alpha 255 everywhere.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  // width * height * 4 bytes
    std::string path;                // where it was read from, for messages
    // A rendered frame's float colours, for EXR and --alpha outputs (docs/command-line.md,
    // HDR and alpha outputs): 4 floats a pixel, the mean of its samples' colours (display
    // values, as the scene's colours are; the EXR writer turns them into linear light),
    // unclamped, and the fraction of them that hit an object. Empty unless the run asked.
    std::vector<float> linear;
    // The outputs write rgba's alpha (and linear's fourth float) as transparency (--alpha);
    // otherwise they are opaque RGB.
    bool write_alpha = false;

    std::uint8_t at(int col, int row, int channel) const {
        return rgba[(static_cast<std::size_t>(row) * width + col) * 4 + channel];
    }
    bool has_transparency() const;  // any alpha below 255
};

}  // namespace clr
