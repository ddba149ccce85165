// Coverage masks: one bit per texel of the packed texel buffer, set where the texel stops a
// ray. The packet kernel tests a billboard's holes in these bits instead of in the RGBA
// texels (32 times less memory to keep in cache), and reads a texel only for a ray's winning
// hit (docs/architecture.md, Coverage masks).
#pragma once

#include <cstdint>
#include <vector>

#include "shared/clr_types.h"

namespace clr {

// Whether a texel with this alpha stops a ray: the kernels' and the reference's rule (only
// CLR_OPAQUE_ALPHA is opaque; docs/scene-format.md, Conventions: Billboards).
constexpr bool texel_stops_rays(std::uint8_t alpha) { return alpha >= CLR_OPAQUE_ALPHA; }

// Sets the bits of the texels rgba[0 .. rgba.size() / 4) at bit index first_texel and on:
// texel k's bit is bit (first_texel + k) % 32 of word (first_texel + k) / 32. Bits of
// transparent texels stay 0. The mask ends CLR_COVERAGE_WINDOW_WORDS zero words after the
// last texel's word: the kernel reads a small image's bits as that many words from its first
// (shared/clr_types.h).
void append_coverage(const std::vector<std::uint8_t>& rgba, std::uint64_t first_texel, std::vector<std::uint32_t>& mask);

}  // namespace clr
