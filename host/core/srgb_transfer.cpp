#include "core/srgb_transfer.h"

#include <cmath>

namespace clr {

double srgb_to_linear(double display) {
    const double magnitude = std::abs(display);
    if (!(magnitude > 0.04045)) return display / 12.92;  // also 0, -0 and NaN
    return std::copysign(std::pow((magnitude + 0.055) / 1.055, 2.4), display);
}

}  // namespace clr
