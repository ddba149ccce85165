// The values an EXR holds (output/exr_values.h): linear light from which the documented rule
// (tests/support/srgb_rule.h, written from IEC 61966-2-1) gives the PNG's byte in float, double
// and long double alike, including for colours within a float's rounding of a byte step's
// rounding threshold, where the rule would otherwise round to the neighbouring byte.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/display_bytes.h"
#include "core/srgb_transfer.h"
#include "output/exr_values.h"
#include "support/srgb_rule.h"

namespace clr {
namespace {

using testing::png_byte_of;
using testing::srgb_encode;

// Display values that matter: each byte's centre and the float neighbours (up to 40 ulps) of
// every rounding threshold (k + 0.5) / 255, where float and double rounding disagree most.
std::vector<float> probing_displays() {
    std::vector<float> displays;
    for (int k = 0; k <= 255; ++k) {
        displays.push_back(k / 255.0f);
        float near = static_cast<float>((k + 0.5) / 255.0);
        for (int step = 0; step < 40; ++step) near = std::nextafter(near, 0.0f);
        for (int step = 0; step <= 80; ++step, near = std::nextafter(near, 2.0f)) displays.push_back(near);
    }
    return displays;
}

TEST(ExrValues, RuleGivesThePngByteInAnyPrecision) {
    int near_threshold = 0;
    for (const float display : probing_displays()) {
        const std::uint8_t byte = display_byte(display);
        const float value = exr_linear_value(display, byte);
        ASSERT_EQ(png_byte_of<float>(value), byte) << "float, display " << display;
        ASSERT_EQ(png_byte_of<double>(value), byte) << "double, display " << display;
        ASSERT_EQ(png_byte_of<long double>(value), byte) << "long double, display " << display;
        // Without the margin these disagree: the raw value's byte in double differs from the PNG's.
        near_threshold += png_byte_of<double>(static_cast<float>(srgb_to_linear(display))) != byte;
    }
    EXPECT_GT(near_threshold, 0) << "the probe must reach values that need the margin";
}

TEST(ExrValues, ValuesAreTheLinearColourWithinTheMargin) {
    for (const float display : probing_displays()) {
        const std::uint8_t byte = display_byte(display);
        const double back = srgb_encode<double>(exr_linear_value(display, byte));
        // Moved by at most the margin, plus float's rounding of the stored value.
        ASSERT_NEAR(back, display, (kRoundingMargin + 1e-3) / 255) << display;
    }
    // Away from a threshold nothing moves: 0.4 (byte 102.0) is 0.1328683 in linear light.
    EXPECT_NEAR(exr_linear_value(0.4f, 102), 0.1328683f, 1e-7);
    // 0.5 is byte 127.5 exactly, which rounds up: stored as byte 127.51's linear value.
    EXPECT_NEAR(srgb_encode<double>(exr_linear_value(0.5f, 128)) * 255, 127.5 + kRoundingMargin, 1e-4);
    EXPECT_EQ(exr_linear_value(0.0f, 0), 0.0f);
    EXPECT_EQ(exr_linear_value(1.0f, 255), 1.0f);
}

TEST(ExrValues, ColoursOutsideTheDisplayRangeStayUnclamped) {
    const float bright = exr_linear_value(1.5f, 255);
    EXPECT_NEAR(bright, std::pow(1.555 / 1.055, 2.4), 1e-6);
    EXPECT_NEAR(srgb_encode<double>(bright), 1.5, 1e-6);
    EXPECT_EQ(png_byte_of<float>(bright), 255);
    const float dark = exr_linear_value(-0.25f, 0);
    EXPECT_LT(dark, 0.0f);
    EXPECT_NEAR(srgb_encode<double>(dark), -0.25, 1e-6);
    EXPECT_EQ(png_byte_of<double>(dark), 0);
    EXPECT_TRUE(std::isnan(exr_linear_value(std::numeric_limits<float>::quiet_NaN(), 0)));
    EXPECT_EQ(png_byte_of<float>(std::numeric_limits<float>::quiet_NaN()), 0);
}

// Two pixels: one fully covered, one with 3 of 4 samples' coverage (in display values away
// from the bytes' rounding thresholds, so that the margin moves nothing).
Image two_pixels(bool alpha) {
    Image image;
    image.width = 2;
    image.height = 1;
    image.linear = {0.45f, 0.25f, 1.25f, 1.0f, 0.8f, 0.15f, 0.4f, alpha ? 0.75f : 1.0f};
    for (float c : image.linear) image.rgba.push_back(display_byte(c));
    image.rgba[3] = image.rgba[7] = 255;
    image.write_alpha = alpha;
    return image;
}

TEST(ExrValues, OpaqueFramesHoldTheLinearColourAndAlphaOne) {
    const Image image = two_pixels(false);
    const std::vector<float> values = exr_values(image);
    ASSERT_EQ(values.size(), 8u);
    for (int i : {0, 1, 2, 4, 5, 6}) {
        EXPECT_EQ(values[i], exr_linear_value(image.linear[i], image.rgba[i])) << i;
        EXPECT_EQ(png_byte_of<double>(values[i]), image.rgba[i]) << i;
    }
    EXPECT_EQ(values[3], 1.0f);
    EXPECT_EQ(values[7], 1.0f);
}

TEST(ExrValues, AlphaFramesArePremultipliedInLinearLight) {
    Image image = two_pixels(true);
    image.linear[3] = 0.0f;  // no sample hit the first pixel
    const std::vector<float> values = exr_values(image);
    for (int i : {0, 1, 2}) EXPECT_EQ(values[i], 0.0f) << "no object, no colour";
    EXPECT_EQ(values[3], 0.0f);
    EXPECT_EQ(values[7], 0.75f);
    for (int i : {4, 5, 6}) {
        const double straight = srgb_encode<double>(values[i] / 0.75);  // what a viewer shows
        EXPECT_NEAR(straight, image.linear[i], 1e-6) << i;
        EXPECT_EQ(png_byte_of<float>(values[i] / values[7]), image.rgba[i]) << i;
        EXPECT_EQ(png_byte_of<double>(static_cast<double>(values[i]) / values[7]), image.rgba[i]) << i;
    }
}

}  // namespace
}  // namespace clr
