// Sun lighting, shadows and mirrors in whole kernel images: every MaxDepth renders what the
// reference renders, and the same scene at very different scales gives the same picture.
#include <gtest/gtest.h>

#include "support/image_compare.h"
#include "support/render_helpers.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

// Two parallel mirrors facing each other with the camera between them, looking slightly
// sideways: each pixel's ray walks along the corridor and leaves it, onto a red or green end
// wall, after a number of reflections that grows towards the image centre. Each MaxDepth
// therefore shows a different set of walls, and the rest is background.
Scene mirror_corridor(int max_depth) {
    Scene scene = testing::make_scene({0, 0, 0}, {0.35, 0.05, -1}, {0, 1, 0}, 60, 120, 90);
    scene.max_depth = max_depth;
    scene.background = {0.2, 0.2, 0.6};
    scene.has_sun = true;
    scene.sun_location = {0, 50, 0};
    // Mirror fronts face the corridor's inside: (LL-UL) x (UR-UL) points to z = 0.
    scene.billboards.push_back(testing::make_billboard({-15, 8, -5}, {-15, -8, -5}, {15, 8, -5}, {0, 0, 0}, nullptr, true));
    scene.billboards.push_back(testing::make_billboard({15, 8, 5}, {15, -8, 5}, {-15, 8, 5}, {0, 0, 0}, nullptr, true));
    scene.billboards.push_back(testing::make_billboard({15, 8, -5}, {15, -8, -5}, {15, 8, 5}, {0.9, 0.1, 0.1}));
    scene.billboards.push_back(testing::make_billboard({-15, 8, 5}, {-15, -8, 5}, {-15, 8, -5}, {0.1, 0.9, 0.1}));
    // A lit sphere in the corridor, seen directly and in the mirrors, with its shadow
    // falling on nothing but itself.
    scene.spheres.push_back(testing::make_sphere({4, -1, -2}, 1.2, {1, 0.8, 0.2}));
    scene.spheres.push_back(testing::make_sphere({6, 2.5, -2}, 0.8, {0.3, 0.7, 1.0}));
    return scene;
}

void expect_matches_reference(const Scene& scene, const std::string& what) {
    testing::expect_kernels_match_reference(scene, what, {}, 0.001);
}

TEST(Mirrors, EveryMaxDepthFromZeroToSixMatchesTheReference) {
    Image previous;
    for (int depth = 0; depth <= 6; ++depth) {
        Scene scene = mirror_corridor(depth);
        expect_matches_reference(scene, "MaxDepth " + std::to_string(depth));
        Image image = testing::render_with_kernels(scene);
        if (depth > 0) {
            EXPECT_NE(image.rgba, previous.rgba) << "MaxDepth " << depth << " changed nothing";
        }
        previous = image;
    }
}

TEST(Mirrors, MaxDepthZeroShowsBackgroundInEveryMirror) {
    Scene scene = mirror_corridor(0);
    Image image = testing::render_with_kernels(scene);
    // The centre pixel looks straight into the far mirror: with no reflection allowed it
    // takes the background colour.
    EXPECT_EQ(image.at(60, 45, 0), 51);
    EXPECT_EQ(image.at(60, 45, 1), 51);
    EXPECT_EQ(image.at(60, 45, 2), 153);
}

// A scene with everything (textures with holes, a mirror sphere, a mirror billboard, lit
// spheres casting shadows on each other), scaled about the origin with its camera and sun.
Scene everything_scaled(double scale) {
    auto holes = testing::make_image(8, 8, [](int col, int row) {
        bool hole = (col + row) % 3 == 0;
        return std::array<std::uint8_t, 4>{std::uint8_t(30 * col), std::uint8_t(30 * row), 200, std::uint8_t(hole ? 0 : 255)};
    });
    auto v = [scale](double x, double y, double z) { return Vec3{x, y, z} * scale; };
    Scene scene = testing::make_scene(v(2, 3, 14), v(0, 0, 0), {0, 1, 0}, 55, 160, 120);
    scene.has_sun = true;
    scene.sun_location = v(-30, 40, 20);
    scene.max_depth = 4;
    scene.background = {0.05, 0.05, 0.1};
    scene.spheres.push_back(testing::make_sphere(v(0, 0, 0), 2 * scale, {0.8, 0.3, 0.3}));
    scene.spheres.push_back(testing::make_sphere(v(-1.5, 2.6, 1), 0.9 * scale, {0.3, 0.8, 0.3}));  // shadows the first
    scene.spheres.push_back(testing::make_sphere(v(4, 0.5, -1), 1.5 * scale, {0, 0, 0}, true));
    scene.billboards.push_back(testing::make_billboard(v(-8, 6, -6), v(-8, -4, -6), v(8, 6, -6), {0, 0, 0}, holes));
    scene.billboards.push_back(testing::make_billboard(v(-9, 6, -8), v(-9, -4, -8), v(9, 6, -8), {0.9, 0.9, 0.9}));
    scene.billboards.push_back(testing::make_billboard(v(-7, 3, 4), v(-7, -3, 4), v(-5, 3, -2), {0, 0, 0}, nullptr, true));
    return scene;
}

TEST(Scale, SameImageFromAThousandthToTenThousandTimes) {
    Image unit = testing::render_with_kernels(everything_scaled(1));
    for (double scale : {1e-3, 1e4}) {
        testing::ImageComparison comparison = testing::compare_images(testing::render_with_kernels(everything_scaled(scale)), unit);
        EXPECT_LE(comparison.differing_fraction(), 0.001)
            << "scale " << scale << ": " << comparison.differing << " of " << comparison.pixels << " pixels differ";
    }
}

TEST(Scale, ScaledScenesMatchTheReference) {
    for (double scale : {1e-3, 1.0, 1e4}) expect_matches_reference(everything_scaled(scale), "scale " + std::to_string(scale));
}

}  // namespace
}  // namespace clr
