// clrender compare's arithmetic (docs/command-line.md, Comparing with an image): which pixels
// differ by more than the tolerance, in R, G or B and never in alpha, the list of the most
// different ones, and the heat map's colours, against expectations worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "app/difference_heat_map.h"
#include "app/image_difference.h"

namespace clr {
namespace {

Image filled(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    Image image;
    image.width = width;
    image.height = height;
    image.rgba.resize(static_cast<std::size_t>(width) * height * 4, 255);
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        image.rgba[i] = r;
        image.rgba[i + 1] = g;
        image.rgba[i + 2] = b;
    }
    return image;
}

std::uint8_t& channel(Image& image, int x, int y, int c) {
    return image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4 + c];
}

TEST(CompareDifference, IdenticalImagesDifferNowhere) {
    const Image a = filled(7, 5, 10, 200, 30);
    const ImageDifference difference = difference_of(a, a, 0);
    EXPECT_EQ(difference.differing, 0u);
    EXPECT_EQ(difference.pixels(), 35u);
    EXPECT_EQ(difference.largest, 0);
    EXPECT_TRUE(difference.largest_pixels.empty());
}

// A channel that differs by exactly the tolerance is within it; one step more is not, in each
// of R, G and B, and in both directions.
TEST(CompareDifference, ToleranceIsInclusiveInEveryChannel) {
    for (int tolerance : {0, 1, 2, 17, 254}) {
        for (int c = 0; c < 3; ++c) {
            const Image rendered = filled(4, 3, 0, 0, 0);
            Image image = rendered;
            channel(image, 1, 1, c) = static_cast<std::uint8_t>(tolerance);      // exactly N: the same
            channel(image, 2, 2, c) = static_cast<std::uint8_t>(tolerance + 1);  // N + 1: differs
            const ImageDifference difference = difference_of(rendered, image, tolerance);
            EXPECT_EQ(difference.differing, 1u) << "tolerance " << tolerance << " channel " << c;
            ASSERT_EQ(difference.largest_pixels.size(), 1u);
            EXPECT_EQ(difference.largest_pixels[0].x, 2);
            EXPECT_EQ(difference.largest_pixels[0].y, 2);
            EXPECT_EQ(difference.largest_pixels[0].difference, tolerance + 1);
            EXPECT_EQ(difference.largest, tolerance + 1);
            // The image darker than the render counts as well.
            EXPECT_EQ(difference_of(image, rendered, tolerance).differing, 1u);
        }
    }
    // 255 tolerates everything.
    EXPECT_EQ(difference_of(filled(2, 2, 0, 0, 0), filled(2, 2, 255, 255, 255), 255).differing, 0u);
}

TEST(CompareDifference, AlphaIsNotCompared) {
    const Image rendered = filled(3, 3, 50, 60, 70);
    Image image = rendered;
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x) channel(image, x, y, 3) = 0;
    EXPECT_EQ(difference_of(rendered, image, 0).differing, 0u);
}

TEST(CompareDifference, ListsTheLargestFirstThenInReadingOrder) {
    const Image rendered = filled(10, 10, 100, 100, 100);
    Image image = rendered;
    channel(image, 9, 9, 0) = 140;  // 40
    channel(image, 5, 2, 1) = 40;   // 60
    channel(image, 3, 7, 2) = 160;  // 60, a later row than (5, 2)
    channel(image, 8, 2, 2) = 160;  // 60, the same row as (5, 2), a later column
    channel(image, 0, 0, 0) = 101;  // 1
    const ImageDifference difference = difference_of(rendered, image, 0, 3);
    EXPECT_EQ(difference.differing, 5u);
    EXPECT_EQ(difference.largest, 60);
    ASSERT_EQ(difference.largest_pixels.size(), 3u);  // at most as many as asked for
    EXPECT_EQ(difference.largest_pixels[0].x, 5);
    EXPECT_EQ(difference.largest_pixels[0].y, 2);
    EXPECT_EQ(difference.largest_pixels[1].x, 8);
    EXPECT_EQ(difference.largest_pixels[1].y, 2);
    EXPECT_EQ(difference.largest_pixels[2].x, 3);
    EXPECT_EQ(difference.largest_pixels[2].y, 7);
    const std::array<std::uint8_t, 3> rendered_colour{100, 100, 100}, image_colour{100, 40, 100};
    EXPECT_EQ(difference.largest_pixels[0].rendered, rendered_colour);
    EXPECT_EQ(difference.largest_pixels[0].image, image_colour);
    EXPECT_NEAR(difference.differing_share(), 0.05, 1e-12);
}

TEST(CompareDifference, RefusesImagesOfDifferentSizesAndToleranceOutsideItsRange) {
    EXPECT_THROW(difference_of(filled(3, 2, 0, 0, 0), filled(2, 3, 0, 0, 0), 0), std::invalid_argument);
    EXPECT_THROW(difference_heat_map(filled(3, 2, 0, 0, 0), filled(3, 3, 0, 0, 0), 0), std::invalid_argument);
    EXPECT_THROW(difference_of(filled(1, 1, 0, 0, 0), filled(1, 1, 0, 0, 0), 256), std::invalid_argument);
    EXPECT_THROW(difference_of(filled(1, 1, 0, 0, 0), filled(1, 1, 0, 0, 0), -1), std::invalid_argument);
}

// The scale's stops, as documented: blue at 1/255, cyan at 255^(1/4) (about 4), green at
// 255^(1/2) (about 16), yellow at 255^(3/4) (about 64), red at 255.
TEST(CompareHeatMap, ColourScaleStops) {
    using Colour = std::array<std::uint8_t, 3>;
    EXPECT_EQ(heat_colour(1), (Colour{0, 0, 255}));
    EXPECT_EQ(heat_colour(255), (Colour{255, 0, 0}));
    auto near = [](const Colour& got, const Colour& expected) {
        for (int c = 0; c < 3; ++c)
            if (std::abs(got[c] - expected[c]) > 2) return false;
        return true;
    };
    EXPECT_TRUE(near(heat_colour(4), {0, 255, 255}));
    EXPECT_TRUE(near(heat_colour(16), {0, 255, 0}));
    EXPECT_TRUE(near(heat_colour(64), {255, 255, 0}));
    // Halfway (in log) between blue and cyan: d = 255^(1/8), about 2.
    EXPECT_TRUE(near(heat_colour(2), {0, static_cast<std::uint8_t>(std::lround(255 * 4 * std::log(2.0) / std::log(255.0))), 255}));
    // Larger differences are never closer to blue than smaller ones.
    for (int d = 2; d <= 255; ++d) EXPECT_LE(heat_colour(d)[2], heat_colour(d - 1)[2]) << d;
}

TEST(CompareHeatMap, DifferencesInColourTheRestInDarkGrey) {
    Image rendered = filled(3, 1, 255, 255, 255);
    channel(rendered, 2, 0, 0) = 0;  // a pure cyan pixel of the render
    Image image = rendered;
    channel(image, 0, 0, 1) = 0;    // 255 off: red
    channel(image, 1, 0, 2) = 253;  // 2 off, within a tolerance of 2: context
    const Image map = difference_heat_map(rendered, image, 2);
    ASSERT_EQ(map.width, 3);
    ASSERT_EQ(map.height, 1);
    EXPECT_EQ(map.at(0, 0, 0), 255);
    EXPECT_EQ(map.at(0, 0, 1), 0);
    EXPECT_EQ(map.at(0, 0, 2), 0);
    // White's luminance is 255: grey 255 / 4 = 63.75, so 64.
    for (int c = 0; c < 3; ++c) EXPECT_EQ(map.at(1, 0, c), 64);
    // Cyan (0, 255, 255): (0.7152 + 0.0722) * 255 / 4 = 50.2, so 50.
    for (int c = 0; c < 3; ++c) EXPECT_EQ(map.at(2, 0, c), 50);
    EXPECT_FALSE(map.write_alpha);
}

}  // namespace
}  // namespace clr
