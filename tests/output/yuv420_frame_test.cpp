// rgba_to_yuv420 against the BT.709 limited-range formulas evaluated in doubles, and against
// the 8-bit values of the primaries that every BT.709 encoder gives.
#include "output/yuv420_frame.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace clr {
namespace {

struct YCbCr {
    double y, cb, cr;
};

// The exact values for one R'G'B' triple (ITU-R BT.709-6: Kr 0.2126, Kb 0.0722; limited range).
YCbCr bt709(double r, double g, double b) {
    const double kr = 0.2126, kb = 0.0722, kg = 1 - kr - kb;
    const double luma = kr * r + kg * g + kb * b;
    return {16 + 219.0 / 255 * luma, 128 + 224.0 / 255 * (b - luma) / (2 * (1 - kb)),
            128 + 224.0 / 255 * (r - luma) / (2 * (1 - kr))};
}

Image random_frame(int width, int height, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_int_distribution<int> byte(0, 255);
    Image image;
    image.width = width;
    image.height = height;
    image.rgba.resize(static_cast<std::size_t>(width) * height * 4);
    for (std::uint8_t& value : image.rgba) value = static_cast<std::uint8_t>(byte(random));
    return image;
}

Image solid(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    Image image;
    image.width = width;
    image.height = height;
    image.rgba.resize(static_cast<std::size_t>(width) * height * 4);
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        image.rgba[i] = r;
        image.rgba[i + 1] = g;
        image.rgba[i + 2] = b;
        image.rgba[i + 3] = 255;
    }
    return image;
}

// R'G'B' of a pixel of the frame padded to even size: black outside it.
double channel(const Image& frame, int col, int row, int c) {
    if (col >= frame.width || row >= frame.height) return 0;
    return frame.at(col, row, c);
}

// Checks every plane of the conversion of `frame` against the doubles: each value within 1 of
// the exact one (fixed-point rounding), nearly all of them equal to it rounded.
void expect_matches_formula(const Image& frame) {
    std::vector<std::uint8_t> yuv;
    rgba_to_yuv420(frame, yuv);
    const int width = frame.width + frame.width % 2, height = frame.height + frame.height % 2;
    ASSERT_EQ(yuv.size(), static_cast<std::size_t>(width * height * 3 / 2));
    const std::uint8_t* const luma = yuv.data();
    const std::uint8_t* const cb = luma + width * height;
    const std::uint8_t* const cr = cb + (width / 2) * (height / 2);
    int values = 0, rounded_exactly = 0;
    auto check = [&](double exact, std::uint8_t got, const char* plane, int col, int row) {
        EXPECT_LE(std::fabs(exact - got), 1.0) << plane << " at " << col << "," << row << ": " << exact;
        ++values;
        if (got == static_cast<int>(std::lround(exact))) ++rounded_exactly;
    };
    for (int row = 0; row < height; ++row)
        for (int col = 0; col < width; ++col) {
            const YCbCr exact =
                bt709(channel(frame, col, row, 0), channel(frame, col, row, 1), channel(frame, col, row, 2));
            check(exact.y, luma[row * width + col], "Y'", col, row);
        }
    for (int row = 0; row < height / 2; ++row)
        for (int col = 0; col < width / 2; ++col) {
            double sum[3] = {0, 0, 0};
            for (int dy = 0; dy < 2; ++dy)
                for (int dx = 0; dx < 2; ++dx)
                    for (int c = 0; c < 3; ++c) sum[c] += channel(frame, col * 2 + dx, row * 2 + dy, c);
            const YCbCr exact = bt709(sum[0] / 4, sum[1] / 4, sum[2] / 4);
            check(exact.cb, cb[row * (width / 2) + col], "Cb", col, row);
            check(exact.cr, cr[row * (width / 2) + col], "Cr", col, row);
        }
    EXPECT_GE(rounded_exactly, values * 99 / 100) << "of " << values << " values";
}

TEST(Yuv420Frame, EveryPlaneFollowsTheBt709Formulas) {
    expect_matches_formula(random_frame(64, 36, 1));
    expect_matches_formula(random_frame(1280, 8, 2));  // a frame's width: the vectorised loop's every lane
}

// An odd width or height gains a black column or row: Y' 16, and the blocks along the edge
// average their pixels with black ones.
TEST(Yuv420Frame, OddSizesArePaddedWithBlack) {
    for (const auto& [width, height] : {std::pair{5, 3}, std::pair{1, 1}, std::pair{7, 4}, std::pair{4, 7}}) {
        SCOPED_TRACE(std::to_string(width) + "x" + std::to_string(height));
        const Image frame = random_frame(width, height, 3);
        expect_matches_formula(frame);
        std::vector<std::uint8_t> yuv;
        rgba_to_yuv420(frame, yuv);
        const int padded_width = width + width % 2, padded_height = height + height % 2;
        for (int row = 0; row < padded_height; ++row)
            for (int col = 0; col < padded_width; ++col)
                if (col >= width || row >= height) {
                    EXPECT_EQ(yuv[row * padded_width + col], 16) << col << "," << row;
                }
    }
}

// The primaries, white and black in 8-bit BT.709 limited range (as ITU-R BT.709 tabulates
// them and ffmpeg's bt709 matrix gives them): Y' of white 235, of black 16; red 63/102/240,
// green 173/42/26, blue 32/240/118.
TEST(Yuv420Frame, PrimariesHaveTheirBt709Values) {
    struct Case {
        std::uint8_t r, g, b;
        int y, cb, cr;
    };
    for (const Case& c : {Case{255, 255, 255, 235, 128, 128}, Case{0, 0, 0, 16, 128, 128},
                          Case{255, 0, 0, 63, 102, 240}, Case{0, 255, 0, 173, 42, 26}, Case{0, 0, 255, 32, 240, 118}}) {
        std::vector<std::uint8_t> yuv;
        rgba_to_yuv420(solid(2, 2, c.r, c.g, c.b), yuv);
        ASSERT_EQ(yuv.size(), 6u);
        for (int i = 0; i < 4; ++i) EXPECT_EQ(yuv[i], c.y) << int(c.r) << "," << int(c.g) << "," << int(c.b);
        EXPECT_EQ(yuv[4], c.cb) << int(c.r) << "," << int(c.g) << "," << int(c.b);
        EXPECT_EQ(yuv[5], c.cr) << int(c.r) << "," << int(c.g) << "," << int(c.b);
    }
}

// The alpha byte is ignored: an MP4 has no alpha, and the colour is the colour.
TEST(Yuv420Frame, AlphaDoesNotChangeTheResult) {
    Image frame = random_frame(9, 5, 4);
    std::vector<std::uint8_t> opaque, translucent;
    for (std::size_t i = 3; i < frame.rgba.size(); i += 4) frame.rgba[i] = 255;
    rgba_to_yuv420(frame, opaque);
    for (std::size_t i = 3; i < frame.rgba.size(); i += 4) frame.rgba[i] = static_cast<std::uint8_t>(i * 7);
    rgba_to_yuv420(frame, translucent);
    EXPECT_EQ(opaque, translucent);
}

}  // namespace
}  // namespace clr
