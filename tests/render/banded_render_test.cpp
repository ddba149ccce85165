// A frame larger than the device lets one buffer be renders in bands of rows, with the same
// bytes as a frame rendered whole; a frame whose single row does not fit fails clearly.
#include <gtest/gtest.h>

#include "core/errors.h"
#include "render/renderer.h"
#include "support/opencl_test_device.h"
#include "support/random_scene.h"

namespace clr {
namespace {

Scene test_scene() {
    Scene scene = testing::make_random_scene(77, 8, 8);
    scene.camera_path = {{{3, 5, 30}, {0, 0, 0}}};
    scene.width = 90;
    scene.height = 61;  // not a multiple of the band height
    return scene;
}


TEST(BandedRender, BandsGiveTheSameBytesAsAWholeFrame) {
    Scene scene = test_scene();
    Renderer whole(testing::test_device(), scene);
    Image expected = whole.render_view(scene.camera_path.front());
    EXPECT_EQ(whole.bands_of_last_frame(), 1);

    RendererOptions small;
    small.max_buffer_bytes = 90 * 4 * 7;  // seven rows at a time
    Renderer banded(testing::test_device(), scene, small);
    FrameTiming timing;
    Image image = banded.render_view(scene.camera_path.front(), &timing);
    EXPECT_EQ(banded.bands_of_last_frame(), 9);  // 8 bands of 7 rows and one of 5
    EXPECT_TRUE(image.rgba == expected.rgba);
    EXPECT_GT(timing.kernel_ms, 0);
}

TEST(BandedRender, ARowThatDoesNotFitIsAClearDeviceError) {
    Scene scene = test_scene();
    RendererOptions tiny;
    tiny.max_buffer_bytes = 100;
    Renderer renderer(testing::test_device(), scene, tiny);
    try {
        renderer.render_view(scene.camera_path.front());
        FAIL() << "a 90-pixel row cannot fit in 100 bytes";
    } catch (const DeviceError& error) {
        EXPECT_NE(std::string(error.what()).find("a row of 90 pixels needs 360 bytes"), std::string::npos) << error.what();
    }
}

}  // namespace
}  // namespace clr
