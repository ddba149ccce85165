// --crop in the renderer and the reference: a rectangle of the frame, byte for byte the same
// pixels as the full frame's (docs/command-line.md, Crop), whatever the rectangle's alignment to
// the 16x16 screen tiles, the kernel, the bands, and the frame's sample pattern.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "reference/reference.h"
#include "render/renderer.h"
#include "support/image_rect.h"
#include "support/opencl_test_device.h"
#include "support/random_scene.h"

namespace clr {
namespace {

using testing::cut;

// Several samples per pixel, textured billboards with holes, sun, shadows and mirrors.
Scene test_scene() { return testing::make_sunlit_mirror_scene(); }

constexpr int kFrame = 5;  // an animation frame: its own sample pattern

// Rectangles on and off the tile grid: one pixel, single rows and columns, the corners, a tile
// exactly, and the whole frame.
const std::vector<PixelRect> kCrops = {{0, 90, 0, 61}, {0, 37, 0, 23},  {37, 90, 0, 23}, {0, 37, 23, 61},
                                       {37, 90, 23, 61}, {45, 46, 30, 31}, {16, 32, 16, 32}, {89, 90, 0, 61},
                                       {0, 90, 60, 61}, {17, 81, 5, 58}};

TEST(CropRender, EveryCropIsTheFullFramesPixels) {
    Scene scene = test_scene();
    for (bool tiles : {true, false}) {
        SCOPED_TRACE(tiles ? "screen tiles (packet kernel)" : "brute force");
        RendererOptions options;
        options.screen_tiles = tiles;
        Renderer whole(testing::test_device(), scene, options);
        const Image full = whole.render(scene.camera_path.front(), kFrame);
        for (int band_rows : {0, 7}) {
            options.band_rows = band_rows;  // 7: bands that start inside tiles, and inside the crop
            for (const PixelRect& rect : kCrops) {
                SCOPED_TRACE(format_pixel_rect(rect) + " band rows " + std::to_string(band_rows));
                options.crop = rect;
                Renderer cropped(testing::test_device(), scene, options);
                Image image = cropped.render(scene.camera_path.front(), kFrame);
                ASSERT_EQ(image.width, rect.width());
                ASSERT_EQ(image.height, rect.height());
                EXPECT_TRUE(image.rgba == cut(full, rect).rgba);
            }
        }
    }
}

TEST(CropRender, ProgressReportsTheCropsRows) {
    Scene scene = test_scene();
    RendererOptions options;
    options.band_rows = 7;
    options.crop = PixelRect{10, 20, 3, 40};  // 37 rows: bands of 7, 7, 7, 7, 7 and 2
    std::vector<double> fractions;
    options.band_done = [&](double fraction) { fractions.push_back(fraction); };
    Renderer renderer(testing::test_device(), scene, options);
    renderer.render(scene.camera_path.front(), kFrame);
    ASSERT_EQ(fractions.size(), 6u);
    EXPECT_DOUBLE_EQ(fractions.front(), 7.0 / 37);
    EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
}

TEST(CropRender, ACropOutsideTheFrameIsRefused) {
    Scene scene = test_scene();
    RendererOptions options;
    options.crop = PixelRect{0, 91, 0, 10};
    Renderer renderer(testing::test_device(), scene, options);
    EXPECT_THROW(renderer.render(scene.camera_path.front(), kFrame), std::invalid_argument);
}

TEST(CropRender, TheReferenceCropsAlike) {
    Scene scene = test_scene();
    const reference::CameraFrame camera = reference::camera_of(scene, scene.camera_path.front());
    const Image full = reference::render(scene, camera, kFrame);
    for (const PixelRect& rect : {PixelRect{0, 37, 0, 23}, PixelRect{37, 90, 23, 61}, PixelRect{45, 46, 30, 31}}) {
        SCOPED_TRACE(format_pixel_rect(rect));
        Image image = reference::render(scene, camera, kFrame, {}, rect);
        ASSERT_EQ(image.width, rect.width());
        ASSERT_EQ(image.height, rect.height());
        EXPECT_TRUE(image.rgba == cut(full, rect).rgba);
    }
}

TEST(PixelRect, ParsesFourHalfOpenBoundsAndRefusesTheRest) {
    auto rect = parse_pixel_rect("1,20,3,40");
    ASSERT_TRUE(rect);
    EXPECT_EQ(*rect, (PixelRect{1, 20, 3, 40}));
    EXPECT_EQ(rect->width(), 19);
    EXPECT_EQ(rect->height(), 37);
    EXPECT_TRUE(rect->inside(20, 40));
    EXPECT_FALSE(rect->inside(19, 40));
    for (const char* bad : {"", "1,2,3", "1,2,3,4,5", "5,5,0,4", "6,5,0,4", "0,4,3,3", "-1,2,0,3", "a,b,c,d",
                            "1.5,2,0,3", "0,9999999,0,3", " 0,2,0,3"})
        EXPECT_FALSE(parse_pixel_rect(bad)) << bad;
}

}  // namespace
}  // namespace clr
