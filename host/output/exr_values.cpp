#include "output/exr_values.h"

#include <algorithm>
#include <cmath>

#include "core/srgb_transfer.h"

namespace clr {

namespace {

// exr_linear_value() before its rounding to float, so that a premultiplied value is rounded once.
double linear_value(float display, std::uint8_t byte) {
    if (std::isnan(display)) return display;
    double kept = display;
    if (byte > 0) kept = std::max(kept, (byte - 0.5 + kRoundingMargin) / 255.0);
    if (byte < 255) kept = std::min(kept, (byte + 0.5 - kRoundingMargin) / 255.0);
    return srgb_to_linear(kept);
}

}  // namespace

float exr_linear_value(float display, std::uint8_t byte) { return static_cast<float>(linear_value(display, byte)); }

std::vector<float> exr_values(const Image& image) {
    std::vector<float> values(image.linear.size());
    for (std::size_t i = 0; i < values.size(); i += 4) {
        const double coverage = image.write_alpha ? image.linear[i + 3] : 1.0;
        for (std::size_t c = 0; c < 3; ++c) {
            const double linear = linear_value(image.linear[i + c], image.rgba[i + c]);
            values[i + c] = coverage == 0 ? 0.0f : static_cast<float>(coverage * linear);
        }
        values[i + 3] = static_cast<float>(coverage);
    }
    return values;
}

}  // namespace clr
