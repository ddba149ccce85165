// --alpha's convention (output/alpha_convention.h) on hand-made pixels: the colour of the
// samples that hit (the background's share taken out of the mean colour), straight, with the
// coverage; the EXR writer premultiplies it in linear light (exr_values_test.cpp).
#include <gtest/gtest.h>

#include "output/alpha_convention.h"

namespace clr {
namespace {

// Three pixels, 4 samples each, background (0.2, 0.4, 0.6): none hit, 3 of 4 hit a colour
// (1.0, 0.0, 0.4), all hit a colour (1.5, 0.25, 0.5) (above 1: unclamped).
Image three_pixels() {
    Image image;
    image.width = 3;
    image.height = 1;
    image.linear = {0.2f, 0.4f, 0.6f, 0.0f,  //
                    0.75f * 1.0f + 0.25f * 0.2f, 0.25f * 0.4f, 0.75f * 0.4f + 0.25f * 0.6f, 0.75f,
                    1.5f, 0.25f, 0.5f, 1.0f};
    image.rgba = {51, 102, 153, 255, 204, 26, 128, 255, 255, 64, 128, 255};
    return image;
}

const Vec3 kBackground{0.2, 0.4, 0.6};

TEST(AlphaConvention, FloatsHoldTheHitColourAndTheCoverage) {
    Image image = three_pixels();
    apply_alpha_convention(image, kBackground, 4);
    EXPECT_TRUE(image.write_alpha);
    // No hit: the mean left as it is (the EXR writes 0 there). 3 of 4: (m - B/4) / (3/4), the
    // hit colour (1.0, 0.0, 0.4). All: the mean, above 1 unclamped.
    const float expected[] = {0.2f, 0.4f, 0.6f, 0, 1.0f, 0, 0.4f, 0.75f, 1.5f, 0.25f, 0.5f, 1};
    for (int i = 0; i < 12; ++i) EXPECT_NEAR(image.linear[i], expected[i], 1e-6) << i;
    EXPECT_EQ(image.linear[11], 1.0f);
}

TEST(AlphaConvention, PngIsStraight) {
    Image image = three_pixels();
    apply_alpha_convention(image, kBackground, 4);
    EXPECT_TRUE(image.write_alpha);
    // No hit: the background's bytes, transparent. 3 of 4: the hit colour alone, alpha
    // round(0.75 * 255) = 191. All: the bytes as without --alpha, opaque.
    const std::vector<std::uint8_t> expected = {51, 102, 153, 0, 255, 0, 102, 191, 255, 64, 128, 255};
    EXPECT_EQ(image.rgba, expected);
}

TEST(AlphaConvention, CoverageSnapsToWholeSamples) {
    Image image = three_pixels();
    image.linear[11] = 0.99999994f;  // a device whose n / n is not exactly 1
    image.linear[3] = 1e-7f;
    apply_alpha_convention(image, kBackground, 4);
    EXPECT_EQ(image.linear[11], 1.0f);
    EXPECT_EQ(image.linear[3], 0.0f);
    EXPECT_EQ(image.rgba[11], 255);
    EXPECT_EQ(image.rgba[3], 0);
}

}  // namespace
}  // namespace clr
