// An animation's frame count is a product of two numbers from the scene (camera keys times
// frames per segment): it must be checked in full, never wrap around into a negative count
// or a still.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "scene/camera_path.h"
#include "support/scene_json.h"

namespace clr {
namespace {

using namespace testing::scene_json;

// A scene whose camera visits `keys` positions.
Json path_scene(int keys) {
    Json scene = minimal_scene();
    scene.erase("eye");
    Json eyes = Json::array();
    for (int i = 0; i < keys; ++i) eyes.push_back({0, 0, 5 + 0.001 * i});
    scene["eyeLocations"] = eyes;
    return scene;
}

TEST(AnimationLength, ProductOfKeysAndFramesPerSegmentIsChecked) {
    // 30000 keys x 100000 frames a segment: 2999900001 frames, which wrapped to a negative int.
    Json scene = path_scene(30000);
    scene["clrender"] = {{"frames_per_segment", 100000}};
    EXPECT_TRUE(FailsAt(scene, "/clrender/frames_per_segment",
                        "the animation would have (30000 keys - 1) x 100000 frames per segment + 1 = 2999900001 frames, "
                        "more than the limit of 1000000"));
}

TEST(AnimationLength, ProductThatWrapsToOneIsChecked) {
    // (2^16 + 1 - 1) x 2^16 + 1 = 2^32 + 1 frames: 1 in 32 bits, a still.
    Json scene = path_scene(65537);
    scene["clrender"] = {{"frames_per_segment", 65536}};
    EXPECT_TRUE(FailsAt(scene, "/clrender/frames_per_segment", "= 4294967297 frames"));
}

TEST(AnimationLength, DefaultFramesPerSegmentCountsToo) {
    // At the default 10 frames a segment, 100001 keys make 1000001 frames.
    EXPECT_TRUE(FailsAt(path_scene(100001), "/eyeLocations", "(100001 keys - 1) x 10 frames per segment + 1 = 1000001"));
    EXPECT_EQ(animation_frame_count(parse(path_scene(100000))), 999991);
}

TEST(AnimationLength, TheLimitItselfIsAllowed) {
    Json scene = path_scene(28);
    scene["clrender"] = {{"frames_per_segment", 37037}};  // 27 x 37037 + 1 = 1000000
    EXPECT_EQ(animation_frame_count(parse(scene)), 1000000);
    Json longer = path_scene(11);
    longer["clrender"] = {{"frames_per_segment", 100000}};  // 10 x 100000 + 1
    EXPECT_TRUE(FailsAt(longer, "/clrender/frames_per_segment", "= 1000001 frames"));
}

TEST(AnimationLength, SceneBuiltInCodeCannotWrapEither) {
    Scene scene;
    scene.camera_path.assign(65537, CameraKey{{0, 0, 5}, {0, 0, 0}});
    scene.animation.frames_per_segment = 65536;
    EXPECT_THROW(animation_frame_count(scene), std::length_error);
}

}  // namespace
}  // namespace clr
