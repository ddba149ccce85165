// Scenes that break naive float32 code, each compared with the double-precision reference:
// at most 0.1% of pixels may differ by more than 1/255 (SPEC: accurate to the last pixel).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "support/image_compare.h"
#include "support/render_helpers.h"
#include "render/device_camera.h"
#include "support/scene_builder.h"
#include "support/stage_runner.h"

namespace clr {
namespace {

// Checks float and double kernels; double must be at least as close as float.
// No NaN or infinite colour anywhere, checked on the stage kernels' float outputs (a NaN
// would be hidden by the conversion to bytes): primary rays, their hits, their shading.
void expect_no_nan(const Scene& scene, const std::string& what) {
    testing::StageRunner runner(scene);
    const CameraKey& key = scene.camera_path.front();
    std::vector<ClrRay> rays = runner.raygen(make_device_camera(key.eye, key.lookat, scene.up, scene.fov_degrees, scene.width, scene.height));
    std::vector<ClrHit> hits = runner.intersect(rays);
    testing::ShadeOutput shaded = runner.shade(rays, hits, 0);
    int bad = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        bad += std::isnan(hits[i].t);
        for (int k = 0; k < 4; ++k) bad += !std::isfinite(shaded.colors[i].s[k]) || !std::isfinite(rays[i].direction.s[k]);
    }
    EXPECT_EQ(bad, 0) << what << ": NaN or infinite values";
}

void expect_close_to_reference(const Scene& scene, const std::string& what) {
    expect_no_nan(scene, what);
    Image reference = testing::render_with_reference(scene);
    RendererOptions in_double;
    in_double.double_precision = true;
    testing::ImageComparison double_comparison = testing::compare_images(testing::render_with_kernels(scene, in_double), reference);
    EXPECT_LE(double_comparison.differing_fraction(), 0.001) << what << " in double";
    testing::ImageComparison comparison = testing::compare_images(testing::render_with_kernels(scene), reference);
    std::cout << what << " (double): " << double_comparison.differing << " pixels differ by more than 1/255, largest "
              << double_comparison.max_channel_difference << "/255\n";
    std::cout << what << ": " << comparison.differing << " of " << comparison.pixels << " pixels differ by more than 1/255 ("
              << 100 * comparison.differing_fraction() << "%), largest difference " << comparison.max_channel_difference
              << "/255\n";
    EXPECT_LE(comparison.differing_fraction(), 0.001) << what << ": " << comparison.differing << " pixels differ";
}

std::shared_ptr<Image> checker(int size) {
    return testing::make_image(size, size, [](int col, int row) {
        bool dark = (col + row) % 2 == 0;
        return std::array<std::uint8_t, 4>{std::uint8_t(dark ? 40 : 230), 120, std::uint8_t(dark ? 200 : 30), 255};
    });
}

// A small scene with a lit sphere, a shadow, a textured billboard and a mirror, placed at
// `origin` and seen from `origin + (0, 1, 8)` (all sizes about 1).
Scene small_world(const Vec3& origin) {
    Scene scene = testing::make_scene(origin + Vec3{0.5, 1.2, 8}, origin, {0, 1, 0}, 50, 160, 120);
    scene.has_sun = true;
    scene.sun_location = origin + Vec3{20, 30, 15};
    scene.spheres.push_back(testing::make_sphere(origin, 1, {0.9, 0.4, 0.2}));
    scene.spheres.push_back(testing::make_sphere(origin + Vec3{0.7, 1.6, 0.6}, 0.4, {0.2, 0.9, 0.4}));
    scene.spheres.push_back(testing::make_sphere(origin + Vec3{-2.2, 0, 0.5}, 0.8, {0, 0, 0}, true));
    scene.billboards.push_back(
        testing::make_billboard(origin + Vec3{-4, 3, -3}, origin + Vec3{-4, -2, -3}, origin + Vec3{4, 3, -3}, {0, 0, 0}, checker(16)));
    return scene;
}

TEST(Stress, UnitSphereTenThousandAwayThroughANarrowLens) {
    Scene scene = testing::make_scene({0, 0, 1e4}, {0, 0, 0}, {0, 1, 0}, 1.5, 160, 120);
    scene.has_sun = true;
    scene.sun_location = {1e4, 1e4, 1e4};
    scene.spheres.push_back(testing::make_sphere({0, 0, 0}, 1, {0.8, 0.8, 0.2}));
    scene.spheres.push_back(testing::make_sphere({1.5, 0.5, -3}, 0.5, {0.2, 0.8, 0.8}));
    expect_close_to_reference(scene, "sphere 1e4 away, fov 1.5");
}

TEST(Stress, GroundSphereOfRadiusOneHundredThousand) {
    Scene scene = testing::make_scene({0, 1, 0}, {0, 0.6, -20}, {0, 1, 0}, 70, 200, 120);
    scene.has_sun = true;
    scene.sun_location = {50, 200, 80};
    scene.spheres.push_back(testing::make_sphere({0, -1e5, 0}, 1e5, {0.3, 0.7, 0.3}));
    scene.spheres.push_back(testing::make_sphere({1, 0.5, -6}, 0.5, {0.9, 0.2, 0.2}));  // casts a shadow on the ground
    scene.background = {0.5, 0.7, 1.0};
    expect_close_to_reference(scene, "ground sphere r=1e5, eye 1 above");
}

TEST(Stress, SpheresOfRadiusOneThousandth) {
    Scene scene = testing::make_scene({0, 0, 0.01}, {0, 0, 0}, {0, 1, 0}, 40, 160, 120);
    scene.has_sun = true;
    scene.sun_location = {1, 1, 1};
    scene.spheres.push_back(testing::make_sphere({0, 0, 0}, 1e-3, {0.9, 0.9, 0.9}));
    scene.spheres.push_back(testing::make_sphere({0.0015, 0.001, -0.002}, 5e-4, {0.9, 0.3, 0.3}));
    expect_close_to_reference(scene, "spheres of radius 1e-3");
}

TEST(Stress, WholeSceneTranslatedByOneHundredThousand) {
    expect_close_to_reference(small_world({0, 0, 0}), "small world at the origin");
    expect_close_to_reference(small_world({1e5, 1e5, -1e5}), "small world translated by 1e5");
}

TEST(Stress, CameraPathThroughABillboardsPlane) {
    for (double z : {0.5, 0.01, 1e-4, 0.0, -1e-4, -0.01, -0.5}) {
        Scene scene = testing::make_scene({0.3, 0.2, z}, {0.3, 0.2, z - 1}, {0, 1, 0}, 90, 120, 90);
        // The billboard's plane is z = 0; the camera crosses it while looking along -z, and a
        // second, tilted one is seen edge-on.
        scene.billboards.push_back(testing::make_billboard({-2, 2, 0}, {-2, -2, 0}, {2, 2, 0}, {0, 0, 0}, checker(8)));
        scene.billboards.push_back(testing::make_billboard({-3, 3, -5}, {-3, -3, -5}, {3, 3, -5}, {0.2, 0.3, 0.9}));
        scene.spheres.push_back(testing::make_sphere({0.5, 0, -2}, 0.5, {0.9, 0.9, 0.1}));
        expect_close_to_reference(scene, "eye at z = " + std::to_string(z));
    }
}

// Abutting billboards seen at grazing angles: no crack between them may show what is behind.
TEST(Stress, AbuttingBillboardsAtGrazingAnglesLeaveNoCracks) {
    Scene scene = testing::make_scene({0.37, 0.25, 12}, {0.2, 0, -30}, {0, 1, 0}, 40, 240, 120);
    scene.background = {1, 0, 1};  // a crack would show magenta
    for (int i = -6; i < 6; ++i)
        for (int j = 0; j < 40; ++j) {
            // A floor of 1x1 tiles at y = 0, seen from 0.25 above: grazing far away.
            double x = i, z = -j;
            Color color = (i + j) % 2 ? Color{0.8, 0.8, 0.8} : Color{0.2, 0.2, 0.2};
            scene.billboards.push_back(testing::make_billboard({x, 0, z - 1}, {x, 0, z}, {x + 1, 0, z - 1}, color));
        }
    scene.billboards.push_back(testing::make_billboard({-50, 0, 5}, {-50, -0.0001, 5}, {50, 0, 5}, {0, 0, 0}));
    expect_close_to_reference(scene, "grazing floor of abutting billboards");
    // A crack is a magenta pixel between two floor pixels (left and right, or above and below).
    Image image = testing::render_with_kernels(scene);
    auto magenta = [&image](int col, int row) {
        return image.at(col, row, 0) == 255 && image.at(col, row, 1) == 0 && image.at(col, row, 2) == 255;
    };
    int cracks = 0;
    for (int row = 1; row + 1 < image.height; ++row)
        for (int col = 1; col + 1 < image.width; ++col)
            cracks += magenta(col, row) && ((!magenta(col - 1, row) && !magenta(col + 1, row)) ||
                                            (!magenta(col, row - 1) && !magenta(col, row + 1)));
    EXPECT_EQ(cracks, 0);
}

TEST(Stress, SphereWhoseSurfaceTouchesTheEye) {
    Scene scene = testing::make_scene({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90, 120, 90);
    scene.has_sun = true;
    scene.sun_location = {3, 5, 2};
    scene.spheres.push_back(testing::make_sphere({0, 0, -1}, 1, {0.8, 0.5, 0.3}));     // eye on its surface, looking in
    scene.spheres.push_back(testing::make_sphere({1.2, 0, 0}, 1.2, {0.3, 0.5, 0.8}));   // eye on its surface, beside
    scene.billboards.push_back(testing::make_billboard({-5, 5, -6}, {-5, -5, -6}, {5, 5, -6}, {0.9, 0.9, 0.9}));
    expect_close_to_reference(scene, "spheres touching the eye");
}

}  // namespace
}  // namespace clr
