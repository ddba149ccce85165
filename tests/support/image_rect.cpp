#include "support/image_rect.h"

#include <cstddef>

namespace clr::testing {

Image cut(const Image& full, const PixelRect& rect) {
    Image part;
    part.width = rect.width();
    part.height = rect.height();
    for (int row = rect.y0; row < rect.y1; ++row)
        for (int col = rect.x0; col < rect.x1; ++col)
            for (int c = 0; c < 4; ++c) part.rgba.push_back(full.at(col, row, c));
    return part;
}

void paste(Image& whole, const Image& part, const PixelRect& rect) {
    for (int row = 0; row < rect.height(); ++row)
        for (int col = 0; col < rect.width(); ++col)
            for (int c = 0; c < 4; ++c)
                whole.rgba[(static_cast<std::size_t>(rect.y0 + row) * whole.width + rect.x0 + col) * 4 + c] =
                    part.at(col, row, c);
}

}  // namespace clr::testing
