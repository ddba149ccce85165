#include "app/image_difference.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace clr {
namespace {

// The order of the list: a larger difference first, then reading order.
bool listed_before(const PixelDifference& a, const PixelDifference& b) {
    if (a.difference != b.difference) return a.difference > b.difference;
    if (a.y != b.y) return a.y < b.y;
    return a.x < b.x;
}

PixelDifference pixel_difference(const Image& rendered, const Image& image, int x, int y, int difference) {
    PixelDifference pixel;
    pixel.x = x;
    pixel.y = y;
    pixel.difference = difference;
    for (int c = 0; c < 3; ++c) {
        pixel.rendered[c] = rendered.at(x, y, c);
        pixel.image[c] = image.at(x, y, c);
    }
    return pixel;
}

}  // namespace

int channel_difference(const Image& rendered, const Image& image, int x, int y) {
    int largest = 0;
    for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(rendered.at(x, y, c) - image.at(x, y, c)));
    return largest;
}

ImageDifference difference_of(const Image& rendered, const Image& image, int tolerance, std::size_t listed) {
    if (rendered.width != image.width || rendered.height != image.height)
        throw std::invalid_argument("difference_of: images of different sizes");
    if (tolerance < 0 || tolerance > 255)
        throw std::invalid_argument("difference_of: tolerance " + std::to_string(tolerance) + " is not in 0..255");
    ImageDifference result;
    result.width = rendered.width;
    result.height = rendered.height;
    result.tolerance = tolerance;
    // A heap whose front is the listed pixel that would leave the list first: at most
    // `listed` pixels are kept however many differ.
    std::vector<PixelDifference>& kept = result.largest_pixels;
    for (int y = 0; y < rendered.height; ++y) {
        for (int x = 0; x < rendered.width; ++x) {
            const int difference = channel_difference(rendered, image, x, y);
            result.largest = std::max(result.largest, difference);
            if (difference <= tolerance) continue;
            ++result.differing;
            if (listed == 0) continue;
            PixelDifference pixel = pixel_difference(rendered, image, x, y, difference);
            if (kept.size() < listed) {
                kept.push_back(pixel);
                std::push_heap(kept.begin(), kept.end(), listed_before);
            } else if (listed_before(pixel, kept.front())) {
                std::pop_heap(kept.begin(), kept.end(), listed_before);
                kept.back() = pixel;
                std::push_heap(kept.begin(), kept.end(), listed_before);
            }
        }
    }
    std::sort_heap(kept.begin(), kept.end(), listed_before);
    return result;
}

}  // namespace clr
