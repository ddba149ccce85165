#include "core/srgb_transfer.h"

#include <array>
#include <cmath>

namespace clr {
namespace {

std::array<float, 256> linear_table() {
    std::array<float, 256> table{};
    for (int byte = 0; byte < 256; ++byte) {
        const double encoded = byte / 255.0;
        const double linear = encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
        table[byte] = static_cast<float>(linear);
    }
    return table;
}

}  // namespace

float srgb_byte_to_linear(std::uint8_t byte) {
    static const std::array<float, 256> table = linear_table();
    return table[byte];
}

}  // namespace clr
