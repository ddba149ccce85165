// srgb_to_linear() against IEC 61966-2-1's published figures and its continuation beyond
// [0, 1] (core/srgb_transfer.h).
#include <gtest/gtest.h>

#include <cmath>

#include "core/srgb_transfer.h"
#include "support/srgb_rule.h"

namespace clr {
namespace {

TEST(SrgbTransfer, StandardPoints) {
    EXPECT_EQ(srgb_to_linear(0.0), 0.0);
    EXPECT_DOUBLE_EQ(srgb_to_linear(1.0), 1.0);
    // Mid grey: 0.5 encoded is 21.4% of white's light (a figure every colour text quotes).
    EXPECT_NEAR(srgb_to_linear(0.5), 0.214041140, 1e-9);
    // The linear segment: up to 0.04045, c / 12.92.
    EXPECT_DOUBLE_EQ(srgb_to_linear(0.04), 0.04 / 12.92);
    EXPECT_DOUBLE_EQ(srgb_to_linear(0.04045), 0.04045 / 12.92);
    EXPECT_DOUBLE_EQ(srgb_to_linear(0.2), std::pow(0.255 / 1.055, 2.4));
    // Byte 128 / 255 is 0.2158605 in linear light.
    EXPECT_NEAR(srgb_to_linear(128 / 255.0), 0.2158605, 1e-7);
}

TEST(SrgbTransfer, ContinuesBeyondTheDisplayRange) {
    EXPECT_DOUBLE_EQ(srgb_to_linear(1.5), std::pow(1.555 / 1.055, 2.4));
    EXPECT_GT(srgb_to_linear(1.5), 1.0);
    EXPECT_DOUBLE_EQ(srgb_to_linear(-0.5), -srgb_to_linear(0.5));
    EXPECT_DOUBLE_EQ(srgb_to_linear(-0.01), -0.01 / 12.92);
    EXPECT_TRUE(std::isnan(srgb_to_linear(std::nan(""))));
}

TEST(SrgbTransfer, EncodeUndoesIt) {
    for (int i = -300; i <= 600; ++i) {
        const double c = i / 255.0;
        EXPECT_NEAR(testing::srgb_encode(srgb_to_linear(c)), c, 1e-12) << c;
    }
}

}  // namespace
}  // namespace clr
