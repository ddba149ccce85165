#include "render/coverage_mask.h"

namespace clr {

void append_coverage(const std::vector<std::uint8_t>& rgba, std::uint64_t first_texel, std::vector<std::uint32_t>& mask) {
    const std::uint64_t texels = rgba.size() / 4;
    mask.resize((first_texel + texels + 31) / 32 + CLR_COVERAGE_WINDOW_WORDS, 0u);
    for (std::uint64_t k = 0; k < texels; ++k) {
        if (!texel_stops_rays(rgba[k * 4 + 3])) continue;
        const std::uint64_t bit = first_texel + k;
        mask[bit / 32] |= 1u << (bit % 32);
    }
}

}  // namespace clr
