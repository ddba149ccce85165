// A frame rendered into recycled storage (Renderer::recycle) is the frame rendered into new
// memory: every pixel is written, whatever the storage held before.
#include <gtest/gtest.h>

#include "render/renderer.h"
#include "support/opencl_test_device.h"
#include "support/random_scene.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

TEST(RecycledFrames, RenderIntoOldStorageWithoutStalePixels) {
    Scene scene = testing::make_random_scene(21, 6, 6);
    scene.camera_path = {{{4, 6, 32}, {0, 0, 0}}};
    scene.width = 100;  // not a multiple of the 16-pixel tiles: partial tiles too
    scene.height = 70;
    for (bool tiles : {true, false}) {
        RendererOptions options;
        options.screen_tiles = tiles;
        Renderer renderer(testing::test_device(), scene, options);
        Image fresh = renderer.render(scene.camera_path[0]);

        Image garbage = fresh;
        for (std::size_t i = 0; i < garbage.rgba.size(); ++i) garbage.rgba[i] = static_cast<std::uint8_t>(i * 37 + 11);
        const std::uint8_t* storage = garbage.rgba.data();
        renderer.recycle(std::move(garbage));
        Image reused = renderer.render(scene.camera_path[0]);
        EXPECT_EQ(reused.rgba.data(), storage) << "the recycled storage is used";
        EXPECT_EQ(reused.rgba, fresh.rgba) << (tiles ? "tiles" : "brute force");

        Image small = fresh;
        small.rgba.resize(16);
        renderer.recycle(std::move(small));  // the wrong size: new storage
        EXPECT_EQ(renderer.render(scene.camera_path[0]).rgba, fresh.rgba);
    }
}

}  // namespace
}  // namespace clr
