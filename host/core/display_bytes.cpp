#include "core/display_bytes.h"

#include <algorithm>
#include <cmath>

namespace clr {

std::uint8_t display_byte(float channel) {
    if (std::isnan(channel)) return 0;
    // Float throughout, each step rounded as the kernel rounds it: volatile keeps a compiler
    // allowed to contract (-march with FMA) from fusing the multiply and the add.
    const float scaled = std::clamp(channel, 0.0f, 1.0f) * 255.0f;
    const volatile float shifted = scaled + 0.5f;
    return static_cast<std::uint8_t>(std::floor(shifted));
}

void fill_display_bytes(Image& image) {
    const std::size_t pixels = image.linear.size() / 4;
    image.rgba.resize(pixels * 4);
    for (std::size_t i = 0; i < pixels; ++i) {
        for (int c = 0; c < 3; ++c) image.rgba[i * 4 + c] = display_byte(image.linear[i * 4 + c]);
        image.rgba[i * 4 + 3] = 255;
    }
}

}  // namespace clr
