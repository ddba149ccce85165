// A sphere in front of the eye is bounded by the rectangle around its silhouette: every point
// of the sphere projects inside it, its edges touch the silhouette, and it never reaches
// beyond the projection of the sphere's box (which bounded spheres before).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "kinds/sphere_kind.h"
#include "render/frame_camera.h"
#include "render/object_bounds.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

// The projection of the sphere's axis-aligned box: its eight corners, one at a time.
PixelBounds box_bounds(const ObjectBounds& view, const Sphere& sphere) {
    PixelBounds bounds;
    const double r = sphere.radius;
    for (int bits = 0; bits < 8; ++bits)
        view.add(sphere.center + Vec3{bits & 1 ? r : -r, bits & 2 ? r : -r, bits & 4 ? r : -r}, view.eye(), bounds);
    return bounds;
}

// The projection of points spread over the sphere's surface.
PixelBounds surface_bounds(const ObjectBounds& view, const Sphere& sphere, std::mt19937& random) {
    std::normal_distribution<double> normal;
    PixelBounds bounds;
    for (int i = 0; i < 5000; ++i) {
        const Vec3 direction = normalize(Vec3{normal(random), normal(random), normal(random)});
        view.add(sphere.center + direction * sphere.radius, view.eye(), bounds);
    }
    return bounds;
}

TEST(SpherePixelBounds, RectangleAroundTheSilhouetteWithinTheBoxProjection) {
    std::mt19937 random(23);
    std::uniform_real_distribution<double> spot(-30, 30), size(0.01, 2);
    int checked = 0, tighter = 0;
    for (int view_index = 0; view_index < 12; ++view_index) {
        const Vec3 eye{spot(random), spot(random), spot(random)};
        const Vec3 lookat{spot(random), spot(random), spot(random)};
        const ObjectBounds view(make_frame_camera(eye, lookat, {0, 1, 0}, 20 + 10 * view_index, 1920, 1080, eye));
        for (int i = 0; i < 200; ++i) {
            const Sphere sphere = testing::make_sphere({spot(random), spot(random), spot(random)}, size(random), {1, 1, 1});
            if (!view.box_clearly_in_front(sphere.center, sphere.radius)) continue;
            const PixelBounds bounds = SphereKind::pixel_bounds(view, sphere, {});
            ASSERT_TRUE(bounds.in_front);
            ASSERT_FALSE(bounds.whole_screen);
            const PixelBounds box = box_bounds(view, sphere);
            const PixelBounds surface = surface_bounds(view, sphere, random);
            SCOPED_TRACE(::testing::Message() << "view " << view_index << " sphere " << i);
            // Every sampled point inside (up to rounding, far below the tiles' quarter pixel).
            EXPECT_LE(bounds.col_min, surface.col_min + 1e-6);
            EXPECT_GE(bounds.col_max, surface.col_max - 1e-6);
            EXPECT_LE(bounds.row_min, surface.row_min + 1e-6);
            EXPECT_GE(bounds.row_max, surface.row_max - 1e-6);
            // Touching: the samples come within a small fraction of the sphere's size on screen.
            const double slack = 5e-3 * std::max(surface.col_max - surface.col_min, surface.row_max - surface.row_min) + 1e-6;
            EXPECT_GE(bounds.col_min, surface.col_min - slack);
            EXPECT_LE(bounds.col_max, surface.col_max + slack);
            EXPECT_GE(bounds.row_min, surface.row_min - slack);
            EXPECT_LE(bounds.row_max, surface.row_max + slack);
            // Never beyond the box's projection.
            EXPECT_GE(bounds.col_min, box.col_min - 1e-6);
            EXPECT_LE(bounds.col_max, box.col_max + 1e-6);
            EXPECT_GE(bounds.row_min, box.row_min - 1e-6);
            EXPECT_LE(bounds.row_max, box.row_max + 1e-6);
            tighter += (bounds.col_max - bounds.col_min) < 0.9 * (box.col_max - box.col_min);
            ++checked;
        }
    }
    EXPECT_GT(checked, 500);
    EXPECT_GT(tighter, checked / 10) << "the silhouette's rectangle is often much narrower than the box's projection";
}

TEST(SpherePixelBounds, SphereAtTheCentreOfTheViewIsAsWideAsItsAngle) {
    // A sphere of radius 1 at depth 10 straight ahead, 90 degrees across 320 pixels: its
    // silhouette spans tan(asin(1 / 10)) = 1 / sqrt(99) either side of the centre, in screen
    // coordinates, or 160 / sqrt(99) pixels either side of column 159.5.
    const ObjectBounds view(make_frame_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90, 320, 320));
    const PixelBounds bounds = SphereKind::pixel_bounds(view, testing::make_sphere({0, 0, -10}, 1, {1, 1, 1}), {});
    const double half = 160 / std::sqrt(99.0);
    EXPECT_NEAR(bounds.col_min, 159.5 - half, 1e-4);
    EXPECT_NEAR(bounds.col_max, 159.5 + half, 1e-4);
    EXPECT_NEAR(bounds.row_min, 159.5 - half, 1e-4);
    EXPECT_NEAR(bounds.row_max, 159.5 + half, 1e-4);
}

// Beyond the scene format's coordinates (1e15), where the squares overflow, a sphere is
// bounded by its box's projection, not by infinities or NaNs.
TEST(SpherePixelBounds, BeyondTheSquaresRangeTheBoxProjectionBoundsIt) {
    const ObjectBounds view(make_frame_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90, 320, 320));
    const Sphere far = testing::make_sphere({1e199, 0, -1e200}, 1e198, {1, 1, 1});
    ASSERT_TRUE(view.box_clearly_in_front(far.center, far.radius));
    const PixelBounds bounds = SphereKind::pixel_bounds(view, far, {});
    const PixelBounds box = box_bounds(view, far);
    EXPECT_TRUE(std::isfinite(bounds.col_min) && std::isfinite(bounds.col_max));
    EXPECT_TRUE(std::isfinite(bounds.row_min) && std::isfinite(bounds.row_max));
    EXPECT_EQ(bounds.col_min, box.col_min);
    EXPECT_EQ(bounds.col_max, box.col_max);
    EXPECT_EQ(bounds.row_min, box.row_min);
    EXPECT_EQ(bounds.row_max, box.row_max);
    EXPECT_TRUE(bounds.in_front);
}

}  // namespace
}  // namespace clr
