#include "core/image.h"

#include <cstddef>

namespace clr {

bool Image::has_transparency() const {
    // Alpha is every fourth byte; any alpha below 255 is transparent (docs/scene-format.md,
    // Conventions: Billboards).
    for (std::size_t i = 3; i < rgba.size(); i += 4) {
        if (rgba[i] < 255) return true;
    }
    return false;
}

}  // namespace clr
