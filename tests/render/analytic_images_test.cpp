// Whole images of small scenes whose every pixel is known in closed form, rendered by the
// kernels. These expectations come from geometry worked out here, not from the reference.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "support/render_helpers.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

using Texel = std::array<std::uint8_t, 4>;

std::shared_ptr<Image> random_opaque_image(int width, int height, std::uint32_t seed) {
    std::mt19937 random(seed);
    return testing::make_image(width, height, [&random](int, int) {
        return Texel{std::uint8_t(random() & 255), std::uint8_t(random() & 255), std::uint8_t(random() & 255), 255};
    });
}

void expect_pixel(const Image& image, int col, int row, const Texel& expected) {
    for (int c = 0; c < 3; ++c)
        ASSERT_EQ(image.at(col, row, c), expected[c]) << "pixel (" << col << ", " << row << ") channel " << c;
}

// Camera at distance D on +z with a 90 degree field of view: the image plane at z = 0 spans
// exactly [-D, D]^2, so a square billboard with those corners fills the frame and pixel
// (col, row) sees the centre of texel (col, row) of an image of the same resolution.
TEST(AnalyticImage, BillboardFillingTheFrameShowsEachTexelOnce) {
    const int kSize = 24;
    const double D = 3;
    auto image = random_opaque_image(kSize, kSize, 42);
    Scene scene = testing::make_scene({0, 0, D}, {0, 0, 0}, {0, 1, 0}, 90, kSize, kSize);
    scene.billboards.push_back(testing::make_billboard({-D, D, 0}, {-D, -D, 0}, {D, D, 0}, {0, 0, 0}, image));
    Image rendered = testing::render_with_kernels(scene);
    for (int row = 0; row < kSize; ++row)
        for (int col = 0; col < kSize; ++col)
            expect_pixel(rendered, col, row,
                         {image->at(col, row, 0), image->at(col, row, 1), image->at(col, row, 2), 255});
}

// The same billboard seen from behind shows its image mirrored left to right, as a picture
// on glass would.
TEST(AnalyticImage, BillboardSeenFromBehindIsMirrored) {
    const int kSize = 16;
    const double D = 2;
    auto image = random_opaque_image(kSize, kSize, 7);
    Scene scene = testing::make_scene({0, 0, -D}, {0, 0, 0}, {0, 1, 0}, 90, kSize, kSize);
    scene.billboards.push_back(testing::make_billboard({-D, D, 0}, {-D, -D, 0}, {D, D, 0}, {0, 0, 0}, image));
    Image rendered = testing::render_with_kernels(scene);
    for (int row = 0; row < kSize; ++row)
        for (int col = 0; col < kSize; ++col) {
            int mirrored = kSize - 1 - col;
            expect_pixel(rendered, col, row,
                         {image->at(mirrored, row, 0), image->at(mirrored, row, 1), image->at(mirrored, row, 2), 255});
        }
}

// A non-square image on a billboard of the frame's aspect: 32x16 pixels, 90 degrees across
// the width, so the plane at z = 0 spans [-D, D] x [-D/2, D/2].
TEST(AnalyticImage, WideBillboardFillingAWideFrame) {
    const int kWidth = 32, kHeight = 16;
    const double D = 4;
    auto image = random_opaque_image(kWidth, kHeight, 9);
    Scene scene = testing::make_scene({0, 0, D}, {0, 0, 0}, {0, 1, 0}, 90, kWidth, kHeight);
    scene.billboards.push_back(testing::make_billboard({-D, D / 2, 0}, {-D, -D / 2, 0}, {D, D / 2, 0}, {0, 0, 0}, image));
    Image rendered = testing::render_with_kernels(scene);
    for (int row = 0; row < kHeight; ++row)
        for (int col = 0; col < kWidth; ++col)
            expect_pixel(rendered, col, row,
                         {image->at(col, row, 0), image->at(col, row, 1), image->at(col, row, 2), 255});
}

// Transparent texels of a front billboard show the billboard behind it.
TEST(AnalyticImage, TransparentTexelsShowWhatIsBehind) {
    const int kSize = 20;
    const double D = 2;
    auto front = testing::make_image(kSize, kSize, [](int col, int row) {
        bool hole = (col / 4 + row / 4) % 2 == 0;
        return Texel{200, 30, 40, std::uint8_t(hole ? (col % 2 ? 0 : 254) : 255)};  // alpha 254 is a hole too
    });
    Scene scene = testing::make_scene({0, 0, D}, {0, 0, 0}, {0, 1, 0}, 90, kSize, kSize);
    scene.billboards.push_back(testing::make_billboard({-D, D, 0}, {-D, -D, 0}, {D, D, 0}, {0, 0, 0}, front));
    scene.billboards.push_back(testing::make_billboard({-9, 9, -1}, {-9, -9, -1}, {9, 9, -1}, {0.2, 0.4, 1.0}));
    Image rendered = testing::render_with_kernels(scene);
    for (int row = 0; row < kSize; ++row)
        for (int col = 0; col < kSize; ++col) {
            bool hole = (col / 4 + row / 4) % 2 == 0;
            expect_pixel(rendered, col, row, hole ? Texel{51, 102, 255, 255} : Texel{200, 30, 40, 255});
        }
}

// A sphere of radius r at distance d, seen head-on: a pixel shows it exactly when its ray
// passes the centre closer than r, i.e. when d * sin(angle to the axis) < r.
TEST(AnalyticImage, SphereSeenHeadOnCoversTheDiscItSubtends) {
    const int kWidth = 64, kHeight = 48;
    const double d = 10, r = 3, fov = 50;
    Scene scene = testing::make_scene({0, 0, d}, {0, 0, 0}, {0, 1, 0}, fov, kWidth, kHeight);
    scene.background = {0.1, 0.2, 0.3};
    scene.spheres.push_back(testing::make_sphere({0, 0, 0}, r, {1, 0.5, 0}));
    Image rendered = testing::render_with_kernels(scene);

    const double half_width = std::tan(fov * M_PI / 360);
    const double half_height = half_width * kHeight / kWidth;
    int inside = 0, checked = 0;
    for (int row = 0; row < kHeight; ++row)
        for (int col = 0; col < kWidth; ++col) {
            double x = (2 * (col + 0.5) / kWidth - 1) * half_width;
            double y = (1 - 2 * (row + 0.5) / kHeight) * half_height;
            double sin_angle = std::sqrt((x * x + y * y) / (x * x + y * y + 1));
            double miss_distance = d * sin_angle;
            if (std::fabs(miss_distance - r) < 1e-4 * r) continue;  // on the silhouette itself
            ++checked;
            bool on_sphere = miss_distance < r;
            inside += on_sphere;
            expect_pixel(rendered, col, row, on_sphere ? Texel{255, 128, 0, 255} : Texel{26, 51, 77, 255});
        }
    EXPECT_GT(inside, 100);
    EXPECT_GT(checked, kWidth * kHeight - 10);
}

}  // namespace
}  // namespace clr
