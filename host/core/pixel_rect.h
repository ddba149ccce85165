// A rectangle of an image's pixels, half-open like pbrt's --pixelbounds: columns x0 <= x < x1,
// rows y0 <= y < y1 (docs/command-line.md, Crop).
#pragma once

#include <optional>
#include <string>

namespace clr {

struct PixelRect {
    int x0 = 0, x1 = 0, y0 = 0, y1 = 0;

    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    bool inside(int image_width, int image_height) const { return x1 <= image_width && y1 <= image_height; }
    bool operator==(const PixelRect& other) const {
        return x0 == other.x0 && x1 == other.x1 && y0 == other.y0 && y1 == other.y1;
    }
};

// "x0,x1,y0,y1": four non-negative integers with x0 < x1 and y0 < y1; nullopt otherwise.
std::optional<PixelRect> parse_pixel_rect(const std::string& text);

// "x0,x1,y0,y1" again, for messages.
std::string format_pixel_rect(const PixelRect& rect);

}  // namespace clr
