// Where one image's texels sit in the texel buffer, and what the kernels need to know of it
// (compiled_scene packs the images; a billboard's device struct points at its slot).
#pragma once

#include <cstdint>

namespace clr {

struct TextureSlot {
    std::uint32_t offset = 0;  // first texel
    int width = 0, height = 0;
    bool holes = false;  // some alpha below 255: rays must test it
};

}  // namespace clr
