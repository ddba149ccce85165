// Near and far clipping (docs/scene-format.md, Near and far clipping) in whole kernel images
// against the reference: primary rays see only depths from `near` to `far` along the view
// direction, whatever lies nearer or farther; reflected and shadow rays see everything.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "support/render_helpers.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

// A row of spheres going away from the eye, a floor billboard and a mirror sphere, lit by the
// sun: the near depth cuts through the first sphere (its inside shows), the far depth through
// the floor.
Scene row_of_spheres(double near, double far) {
    Scene scene = testing::make_scene({0, 1, 10}, {0, 0, 0}, {0, 1, 0}, 50, 120, 90);
    scene.background = {0.2, 0.3, 0.5};
    scene.has_sun = true;
    scene.sun_location = {5, 12, 8};
    for (int i = 0; i < 5; ++i)
        scene.spheres.push_back(testing::make_sphere({-2.0 + i, 0, 6.0 - 4 * i}, 1.2, {0.9, 0.2 * i, 0.3}));
    scene.spheres.push_back(testing::make_sphere({2.5, 1, 2}, 1, {0, 0, 0}, true));
    scene.billboards.push_back(testing::make_billboard({-20, -1.2, -30}, {-20, -1.2, 12}, {20, -1.2, -30}, {0.6, 0.6, 0.6}));
    scene.clip_near = near;
    scene.clip_far = far;
    return scene;
}

TEST(Clipping, NearAndFarDepthsMatchTheReference) {
    const Scene scene = row_of_spheres(4.5, 17);
    testing::expect_kernels_match_reference(scene, "screen tiles");
    RendererOptions brute_force;
    brute_force.screen_tiles = false;
    testing::expect_kernels_match_reference(scene, "brute force", brute_force);
    RendererOptions double_precision;
    double_precision.double_precision = true;
    testing::expect_kernels_match_reference(scene, "double", double_precision);
    EXPECT_NE(testing::render_with_kernels(scene).rgba,
              testing::render_with_kernels(row_of_spheres(0, std::numeric_limits<double>::infinity())).rgba);
}

// The general program with clipping (FeatureSet::general) renders the same bytes.
TEST(Clipping, TheGeneralProgramRendersTheSameBytes) {
    testing::expect_general_program_renders_the_same(row_of_spheres(4.5, 17));
}

// An object wholly nearer than `near`, or wholly beyond `far`, is not seen: the image is the
// one without it.
TEST(Clipping, ObjectsOutsideTheDepthsVanishFromTheImage) {
    Scene scene = testing::make_scene({0, 0, 10}, {0, 0, 0}, {0, 1, 0}, 60, 64, 48);
    scene.background = {0.1, 0.1, 0.1};
    scene.spheres.push_back(testing::make_sphere({0, 0, 0}, 1, {0, 1, 0}));      // depth 9..11: kept
    scene.spheres.push_back(testing::make_sphere({-0.5, 0, 8}, 0.5, {1, 0, 0}));  // depth 1.5..2.5: too near
    scene.spheres.push_back(testing::make_sphere({3, 2, -20}, 2, {0, 0, 1}));     // depth 28..32: too far
    scene.clip_near = 3;
    scene.clip_far = 25;
    Scene without = scene;
    without.spheres.resize(1);
    EXPECT_EQ(testing::render_with_kernels(scene).rgba, testing::render_with_kernels(without).rgba);
    EXPECT_EQ(testing::render_with_reference(scene).rgba, testing::render_with_reference(without).rgba);
    scene.clip_near = 0;
    scene.clip_far = std::numeric_limits<double>::infinity();
    EXPECT_NE(testing::render_with_kernels(scene).rgba, testing::render_with_kernels(without).rgba);
}

// A wall lying exactly on the far plane, behind a sphere: its depth rounds to either side of
// `far` from pixel to pixel, so it is dropped whole (Scene::kept_far), in the kernels as in the
// reference; a hair nearer, it is drawn whole.
TEST(Clipping, AWallOnTheFarPlaneIsDroppedWhole) {
    Scene scene = testing::make_scene({0, 0, 20}, {0, 0, 0}, {0, 1, 0}, 60, 100, 100);
    scene.background = {1, 0.9, 0.9};
    scene.spheres.push_back(testing::make_sphere({0, 0, 5}, 2, {0, 1, 0}));
    scene.billboards.push_back(testing::make_billboard({-30, 30, 0}, {-30, -30, 0}, {30, 30, 0}, {0, 0.2, 1}));
    scene.clip_far = 20;
    Scene without = scene;
    without.billboards.clear();
    EXPECT_EQ(testing::render_with_kernels(scene).rgba, testing::render_with_kernels(without).rgba);
    EXPECT_EQ(testing::render_with_reference(scene).rgba, testing::render_with_reference(without).rgba);
    testing::expect_kernels_match_reference(scene, "wall on the far plane");
    scene.clip_far = 20.001;
    const Image kept = testing::render_with_kernels(scene);
    EXPECT_EQ(kept.at(2, 2, 2), 255) << "the wall, a hair nearer than far, is drawn";
    testing::expect_kernels_match_reference(scene, "wall a hair nearer");
}

}  // namespace
}  // namespace clr
