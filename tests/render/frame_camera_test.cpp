// The host's frame camera holds exactly the values the kernels get, so that the screen tiles
// bound the kernels' float rays, not rays of a slightly different camera.
#include "render/frame_camera.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace clr {
namespace {

void expect_float_values(const Vec3& host, const clr_float4& device, const char* what) {
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(host[i], static_cast<double>(static_cast<float>(host[i]))) << what << " is not rounded to float";
        EXPECT_EQ(static_cast<double>(device.s[i]), host[i]) << what << " differs from the kernels' value";
    }
}

TEST(FrameCamera, HoldsExactlyTheKernelsFloatValues) {
    Scene scene = testing::make_scene({1e5 + 0.1, -3.3, 7.7}, {1e5 - 4.9, 2.2, -9.1}, {0.1, 1, 0.3}, 47, 97, 61);
    scene.sampling.samples_per_pixel = 4;
    FrameCamera camera = frame_camera(scene, scene.camera_path.front(), 3);
    ClrCamera device = camera.device();
    expect_float_values(camera.eye, device.eye, "eye");
    expect_float_values(camera.forward, device.forward, "forward");
    expect_float_values(camera.right, device.right, "right");
    expect_float_values(camera.up, device.up, "up");
    EXPECT_EQ(device.width, 97);
    EXPECT_EQ(device.height, 61);
    EXPECT_EQ(device.samples, 4);
    EXPECT_EQ(device.frame_seed, camera.frame_seed);
}

TEST(FrameCamera, TheOriginIsTheEyeOfTheKey) {
    Scene scene = testing::make_scene({1e5 + 0.1, -3.3, 7.7}, {0, 0, 0}, {0, 1, 0}, 60, 8, 8);
    FrameCamera camera = frame_camera(scene, scene.camera_path.front(), 0);
    EXPECT_EQ(camera.origin, scene.camera_path.front().eye);
    EXPECT_EQ(camera.eye, Vec3{}) << "positions relative to the eye keep float precision near it";
    EXPECT_EQ(camera.eye_in_scene(), scene.camera_path.front().eye);
}

TEST(FrameCamera, EveryFrameHasItsOwnSampleSeed) {
    Scene scene = testing::make_scene({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60, 8, 8);
    const CameraKey& key = scene.camera_path.front();
    EXPECT_NE(frame_camera(scene, key, 0).frame_seed, frame_camera(scene, key, 1).frame_seed);
    EXPECT_EQ(frame_camera(scene, key, 1).frame_seed, frame_camera(scene, key, 1).frame_seed);
}

}  // namespace
}  // namespace clr
