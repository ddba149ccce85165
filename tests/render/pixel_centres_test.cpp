// first_pixel_from() and last_pixel_to() give the pixel centres that std::ceil() and
// std::floor(), clamped to the image, give: on pixel centres themselves, just beside them,
// at the image's edges and beyond.
#include "render/pixel_centres.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace clr {
namespace {

constexpr int kCount = 1920;  // pixels across

std::vector<double> probe_values() {
    std::vector<double> values = {0.0, -0.0, 1.0, 0.5, 1e-300, -1e-300, 15.0, 16.0, 1919.0, 1918.75,
                                  std::numeric_limits<double>::denorm_min(), -0.25, -1.0, -5e9};
    for (double centre : {1.0, 16.0, 17.0, 1000.0, 1918.0, 1919.0}) {
        values.push_back(std::nextafter(centre, 0.0));
        values.push_back(std::nextafter(centre, 1e9));
    }
    std::mt19937 random(3);
    std::uniform_real_distribution<double> anywhere(-50, kCount + 50);
    for (int i = 0; i < 10000; ++i) values.push_back(anywhere(random));
    return values;
}

TEST(PixelCentres, FirstPixelFromIsTheClampedCeiling) {
    for (double pixel : probe_values()) {
        if (pixel > kCount - 1) continue;  // no pixel's: the caller sets those aside
        const int expected = static_cast<int>(std::clamp(std::ceil(pixel), 0.0, double(kCount) - 1));
        EXPECT_EQ(first_pixel_from(pixel), expected) << pixel;
    }
    EXPECT_EQ(first_pixel_from(-std::numeric_limits<double>::infinity()), 0);
}

TEST(PixelCentres, LastPixelToIsTheClampedFloor) {
    for (double pixel : probe_values()) {
        if (pixel < 0) continue;  // no pixel's: the caller sets those aside
        const int expected = static_cast<int>(std::clamp(std::floor(pixel), 0.0, double(kCount) - 1));
        EXPECT_EQ(last_pixel_to(pixel, kCount), expected) << pixel;
    }
    EXPECT_EQ(last_pixel_to(std::numeric_limits<double>::infinity(), kCount), kCount - 1);
    EXPECT_EQ(last_pixel_to(5e9, kCount), kCount - 1);
}

}  // namespace
}  // namespace clr
