// Every frame renders in bands of rows: bands of any size, starting anywhere in a screen tile,
// give the bytes of a frame rendered in one launch; between bands the renderer runs a check
// that may abandon the frame; a frame whose single row does not fit fails clearly.
#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

#include "core/errors.h"
#include "render/renderer.h"
#include "support/opencl_test_device.h"
#include "support/random_scene.h"

namespace clr {
namespace {

// Several samples per pixel, textured billboards, sun, shadows and mirrors: everything whose
// result could depend on where a band starts.
Scene test_scene() { return testing::make_sunlit_mirror_scene(); }

constexpr int kFrame = 3;  // an animation frame: its own sample pattern

Image render_in_bands(const Scene& scene, RendererOptions options, int* bands) {
    Renderer renderer(testing::test_device(), scene, options);
    Image image = renderer.render(scene.camera_path.front(), kFrame);
    *bands = renderer.bands_of_last_frame();
    return image;
}

TEST(BandedRender, BandsOfAnySizeGiveTheSameBytesAsOneLaunch) {
    Scene scene = test_scene();
    for (bool tiles : {true, false}) {
        SCOPED_TRACE(tiles ? "screen tiles (packet kernel)" : "brute force");
        RendererOptions options;
        options.screen_tiles = tiles;
        options.band_rows = scene.height;
        int bands = 0;
        Image whole = render_in_bands(scene, options, &bands);
        EXPECT_EQ(bands, 1);
        std::set<std::uint32_t> colours;
        for (std::size_t i = 0; i < whole.rgba.size(); i += 4)
            colours.insert(whole.rgba[i] | whole.rgba[i + 1] << 8 | whole.rgba[i + 2] << 16);
        EXPECT_GT(colours.size(), 200u) << "a frame with something to get wrong";

        options.band_rows = 1;
        EXPECT_TRUE(render_in_bands(scene, options, &bands).rgba == whole.rgba) << "bands of 1 row";
        EXPECT_EQ(bands, 61);

        options.band_rows = 7;  // bands start at rows 7, 14, 21, ...: inside screen tiles
        EXPECT_TRUE(render_in_bands(scene, options, &bands).rgba == whole.rgba) << "bands of 7 rows";
        EXPECT_EQ(bands, 9);  // 8 bands of 7 rows and one of 5

        options.band_rows = 0;
        options.band_seconds = 1e-9;  // sized by time: every band as short as the sizer allows
        EXPECT_TRUE(render_in_bands(scene, options, &bands).rgba == whole.rgba) << "bands sized by time";
        EXPECT_GT(bands, 3);
    }
}

TEST(BandedRender, AFrameLargerThanOneBufferRendersInBands) {
    Scene scene = test_scene();
    Renderer whole(testing::test_device(), scene);
    Image expected = whole.render(scene.camera_path.front());

    RendererOptions small;
    small.max_buffer_bytes = 90 * 4 * 7;  // seven rows at a time
    small.band_seconds = 1e6;  // only the buffer decides, however slow the device (Oclgrind)
    Renderer banded(testing::test_device(), scene, small);
    FrameTiming timing;
    Image image = banded.render(scene.camera_path.front(), 0, &timing);
    EXPECT_EQ(banded.bands_of_last_frame(), 9);
    EXPECT_TRUE(image.rgba == expected.rgba);
    EXPECT_GT(timing.kernel_ms, 0);
}

struct StopRequested : std::runtime_error {
    StopRequested() : std::runtime_error("stop") {}
};

TEST(BandedRender, TheCheckBetweenBandsRunsBeforeEachBandAndMayAbandonTheFrame) {
    Scene scene = test_scene();
    int checks = 0;
    int stop_at = 0;  // 0: never
    RendererOptions options;
    options.band_rows = 7;
    options.between_bands = [&] {
        if (++checks == stop_at) throw StopRequested();
    };
    Renderer renderer(testing::test_device(), scene, options);
    Image expected = renderer.render(scene.camera_path.front());
    EXPECT_EQ(checks, 9);

    checks = 0;
    stop_at = 4;
    EXPECT_THROW(renderer.render(scene.camera_path.front()), StopRequested);
    EXPECT_EQ(checks, 4) << "no band after the check that stopped the frame";

    // The renderer is still usable: the next frame is whole and right.
    checks = 0;
    stop_at = 0;
    EXPECT_TRUE(renderer.render(scene.camera_path.front()).rgba == expected.rgba);
}

TEST(BandedRender, ARowThatDoesNotFitIsAClearDeviceError) {
    Scene scene = test_scene();
    RendererOptions tiny;
    tiny.max_buffer_bytes = 100;
    Renderer renderer(testing::test_device(), scene, tiny);
    try {
        renderer.render(scene.camera_path.front());
        FAIL() << "a 90-pixel row cannot fit in 100 bytes";
    } catch (const DeviceError& error) {
        EXPECT_NE(std::string(error.what()).find("a row of 90 pixels needs 360 bytes"), std::string::npos) << error.what();
    }
}

}  // namespace
}  // namespace clr
