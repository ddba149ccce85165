// The raygen kernel against the reference's primary rays, over many camera set-ups.
#include <gtest/gtest.h>

#include <cmath>

#include "reference/reference.h"
#include "render/frame_camera.h"
#include "support/scene_builder.h"
#include "support/stage_runner.h"

namespace clr {
namespace {

struct CameraCase {
    const char* name;
    Vec3 eye, lookat, up;
    double fov;
    int width, height;
};

const CameraCase kCases[] = {
    {"square", {0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60, 64, 64},
    {"wide", {1, 2, 3}, {-2, 0, -4}, {0, 1, 0}, 45, 96, 54},
    {"tall", {0, 10, 0.5}, {0, 0, 0}, {0, 0, 1}, 75, 40, 90},
    {"tilted up", {3, -1, 2}, {0, 0, 0}, {1, 1, 0.3}, 50, 48, 36},
    {"up not orthogonal", {0, 0, 0}, {1, 0, -1}, {0.2, 1, 0.5}, 70, 33, 47},
    {"narrow fov", {0, 0, 1e4}, {0, 0, 0}, {0, 1, 0}, 1.5, 64, 48},
    {"wide fov", {-2, 1, 0}, {5, 1, 1}, {0, 1, 0}, 170, 50, 50},
    {"one pixel", {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 30, 1, 1},
};

class RaygenTest : public ::testing::TestWithParam<CameraCase> {};

TEST_P(RaygenTest, MatchesReferenceRays) {
    const CameraCase& c = GetParam();
    Scene scene = testing::make_scene(c.eye, c.lookat, c.up, c.fov, c.width, c.height);
    scene.spheres.push_back(testing::make_sphere({0, 0, 0}, 1, {1, 1, 1}));
    testing::StageRunner runner(scene);
    std::vector<ClrRay> rays = runner.raygen(make_frame_camera(c.eye, c.lookat, c.up, c.fov, c.width, c.height).device());
    reference::CameraFrame camera = reference::make_camera(c.eye, c.lookat, c.up, c.fov, c.width, c.height);

    // float32 rounding of the basis and of the per-pixel sum: a few ulps of a unit vector,
    // a little more when the plane is wide (tan(85 deg) ~ 11 scales the rounding).
    const double tolerance = 4e-6;
    int worst_col = 0, worst_row = 0;
    double worst = 0;
    for (int row = 0; row < c.height; ++row)
        for (int col = 0; col < c.width; ++col) {
            reference::Ray expected = reference::primary_ray(camera, col, row);
            const ClrRay& ray = rays[row * c.width + col];
            for (int k = 0; k < 3; ++k) {
                double error = std::fabs(ray.direction.s[k] - expected.direction[k]);
                if (error > worst) worst = error, worst_col = col, worst_row = row;
                ASSERT_FLOAT_EQ(ray.origin.s[k], static_cast<float>(expected.origin[k]));
            }
        }
    EXPECT_LT(worst, tolerance) << "at pixel (" << worst_col << ", " << worst_row << ")";
}

INSTANTIATE_TEST_SUITE_P(Cameras, RaygenTest, ::testing::ValuesIn(kCases),
                         [](const auto& info) {
                             std::string name = info.param.name;
                             for (char& ch : name)
                                 if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                             return name;
                         });

// Independent of the reference: row 0 is the top and column 0 the left of the image.
TEST(Raygen, TopLeftPixelLooksUpAndLeft) {
    Scene scene = testing::make_scene({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90, 4, 2);
    scene.spheres.push_back(testing::make_sphere({0, 0, -5}, 1, {1, 1, 1}));
    testing::StageRunner runner(scene);
    std::vector<ClrRay> rays = runner.raygen(make_frame_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90, 4, 2).device());
    const ClrRay& top_left = rays[0];
    const ClrRay& bottom_right = rays[7];
    EXPECT_LT(top_left.direction.s[0], 0);
    EXPECT_GT(top_left.direction.s[1], 0);
    EXPECT_GT(bottom_right.direction.s[0], 0);
    EXPECT_LT(bottom_right.direction.s[1], 0);
    // fov 90 across the width 4: pixel centre x = -0.75 at z = -1, y = 0.25 (half height 0.5).
    double length = std::sqrt(0.75 * 0.75 + 0.25 * 0.25 + 1);
    EXPECT_NEAR(top_left.direction.s[0], -0.75 / length, 1e-6);
    EXPECT_NEAR(top_left.direction.s[1], 0.25 / length, 1e-6);
    EXPECT_NEAR(top_left.direction.s[2], -1 / length, 1e-6);
}

}  // namespace
}  // namespace clr
