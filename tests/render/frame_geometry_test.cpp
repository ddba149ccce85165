// A frame's geometry lists the scene's billboards, then its impostors placed for the frame's
// key, in the scene's order: the order in which the kernels, the BVH and the screen tiles index
// them.
#include "render/frame_geometry.h"

#include <gtest/gtest.h>

#include <memory>

#include "render/impostor_placement.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

bool same_corners(const Billboard& a, const Billboard& b) {
    return a.upper_left == b.upper_left && a.upper_right == b.upper_right && a.lower_left == b.lower_left;
}

Impostor impostor_at(const Vec3& center, Facing facing) {
    Impostor impostor;
    impostor.center = center;
    impostor.width = 1;
    impostor.height = 2;
    impostor.facing = facing;
    return impostor;
}

TEST(FrameGeometry, SceneBillboardsThenImpostorsPlacedForTheKey) {
    Scene scene = testing::make_scene({0, 0, 10}, {0, 0, 0}, {0, 1, 0}, 60, 32, 24);
    scene.spheres.push_back(testing::make_sphere({0, 0, 0}, 1, {1, 0, 0}));
    scene.billboards.push_back(testing::make_billboard({-1, 1, -2}, {-1, -1, -2}, {1, 1, -2}, {0, 1, 0}));
    scene.impostors = {impostor_at({3, 0, 0}, Facing::Upright), impostor_at({-3, 1, 0}, Facing::Free)};

    FrameGeometry frame(scene);
    EXPECT_EQ(frame.billboard_count(), 1u) << "no impostor shows before it is placed";
    const CameraKey key{{5, 4, 9}, {0, 0, 0}};
    frame.place_impostors(key);
    ASSERT_EQ(frame.billboard_count(), 3u);
    EXPECT_EQ(frame.object_count(), 4u);
    EXPECT_EQ(frame.first_impostor(), 1u);
    EXPECT_TRUE(same_corners(frame.billboard(0), scene.billboards[0]));
    EXPECT_EQ(frame.billboard_origin(0), Vec3(0, 0, 0)) << "the scene's billboards are in scene coordinates";
    EXPECT_EQ(frame.impostor_origin(), key.eye);
    EXPECT_EQ(frame.billboard_origin(1), key.eye) << "impostors are placed relative to the key's eye";
    EXPECT_EQ(frame.billboard_origin(2), key.eye);
    PlacementCamera camera(key, scene.up);
    EXPECT_TRUE(same_corners(frame.billboard(1), place_impostor(scene.impostors[0], camera)));
    EXPECT_TRUE(same_corners(frame.billboard(2), place_impostor(scene.impostors[1], camera)));

    const CameraKey other{{-8, 1, 2}, {0, 0, 0}};
    frame.place_impostors(other);
    EXPECT_TRUE(same_corners(frame.billboard(1), place_impostor(scene.impostors[0], PlacementCamera(other, scene.up))));
    EXPECT_FALSE(same_corners(frame.billboard(1), place_impostor(scene.impostors[0], camera))) << "it must turn";
    EXPECT_EQ(frame.billboard_origin(2), other.eye);
}


// Placing over the previous frame's billboards keeps an image only while its view stays
// the one shown: a turn of the camera past another view shows that view's image.
TEST(FrameGeometry, PlacedAgainShowsTheNewKeysView) {
    Scene scene = testing::make_scene({0, 0, 10}, {0, 0, 0}, {0, 1, 0}, 60, 32, 24);
    Impostor impostor = impostor_at({0, 0, 0}, Facing::Upright);
    auto left = std::make_shared<Image>();
    auto right = std::make_shared<Image>();
    impostor.views = {{{-1, 0, 0}, left}, {{1, 0, 0}, right}};
    scene.impostors = {impostor};

    FrameGeometry frame(scene);
    frame.place_impostors({{-9, 0, 1}, {0, 0, 0}});
    EXPECT_EQ(frame.billboard(0).image, left);
    frame.place_impostors({{9, 0, 1}, {0, 0, 0}});
    EXPECT_EQ(frame.billboard(0).image, right) << "the view from the new eye";
    frame.place_impostors({{8, 0, -1}, {0, 0, 0}});
    EXPECT_EQ(frame.billboard(0).image, right);
    frame.place_impostors({{-8, 0, -1}, {0, 0, 0}});
    EXPECT_EQ(frame.billboard(0).image, left);
}

}  // namespace
}  // namespace clr
