#include "support/image_compare.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>

namespace clr::testing {
namespace {

// The largest difference over the colour channels of pixel (col, row) of a and b.
int channel_difference(const Image& a, int col_a, int row_a, const Image& b, int col_b, int row_b) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(a.at(col_a, row_a, c)) - int(b.at(col_b, row_b, c))));
    return worst;
}

// Whether the reference image changes colour next to (col, row): the pixel then straddles
// an edge, where a float32 kernel and the double reference may pick different sides.
bool on_reference_edge(const Image& reference, int col, int row) {
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            int x = col + dx, y = row + dy;
            if (x < 0 || y < 0 || x >= reference.width || y >= reference.height) continue;
            if (channel_difference(reference, x, y, reference, col, row) > 1) return true;
        }
    return false;
}

// "(col, row): kernel r,g,b vs reference r,g,b".
std::string describe_pixel(const Image& kernel, const Image& reference, int col, int row) {
    std::ostringstream text;
    text << "(" << col << ", " << row << "): kernel " << int(kernel.at(col, row, 0)) << ","
         << int(kernel.at(col, row, 1)) << "," << int(kernel.at(col, row, 2)) << " vs reference "
         << int(reference.at(col, row, 0)) << "," << int(reference.at(col, row, 1)) << ","
         << int(reference.at(col, row, 2));
    return text.str();
}

}  // namespace

ImageComparison compare_images(const Image& kernel, const Image& reference) {
    ImageComparison result;
    if (kernel.width != reference.width || kernel.height != reference.height) {
        result.pixels = result.differing = result.differing_off_edge = 1;
        result.first_off_edge = "image sizes differ";
        return result;
    }
    for (int row = 0; row < kernel.height; ++row)
        for (int col = 0; col < kernel.width; ++col) {
            ++result.pixels;
            int difference = channel_difference(kernel, col, row, reference, col, row);
            result.max_channel_difference = std::max(result.max_channel_difference, difference);
            if (difference <= 1) continue;
            if (result.differing++ == 0) result.first_differing = describe_pixel(kernel, reference, col, row);
            if (on_reference_edge(reference, col, row)) continue;
            if (result.differing_off_edge++ == 0) result.first_off_edge = describe_pixel(kernel, reference, col, row);
        }
    return result;
}

}  // namespace clr::testing
