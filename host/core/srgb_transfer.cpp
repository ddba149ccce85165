#include "core/srgb_transfer.h"

#include <array>
#include <cmath>

namespace clr {
namespace {

std::array<float, 256> linear_table() {
    std::array<float, 256> table{};
    for (int byte = 0; byte < 256; ++byte) table[byte] = static_cast<float>(srgb_to_linear(byte / 255.0));
    return table;
}

}  // namespace

double srgb_to_linear(double display) {
    const double magnitude = std::abs(display);
    if (!(magnitude > 0.04045)) return display / 12.92;  // also 0, -0 and NaN
    return std::copysign(std::pow((magnitude + 0.055) / 1.055, 2.4), display);
}

float srgb_byte_to_linear(std::uint8_t byte) {
    static const std::array<float, 256> table = linear_table();
    return table[byte];
}

}  // namespace clr
