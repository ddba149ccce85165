// A sphere clearly in front of the eye is bounded by its box's corners' extreme screen
// coordinates, converted to pixels once each: exactly the bounds that widening by each corner
// gives (ObjectBounds::widen()), so that no tile list changes by a bit.
#include <gtest/gtest.h>

#include <array>
#include <random>

#include "kinds/sphere_kind.h"
#include "render/frame_camera.h"
#include "render/object_bounds.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

// The bounds of widening by each of the sphere's box corners in camera coordinates (the
// centre's, plus or minus the radius along each scene axis), one corner at a time.
PixelBounds corner_by_corner(const ObjectBounds& view, const Sphere& sphere) {
    const Vec3& right = view.right_scaled();
    const Vec3& up = view.up_scaled();
    const Vec3& forward = view.forward();
    const double r = sphere.radius;
    const Vec3 rel = sphere.center - view.eye();
    const Vec3 center{dot(rel, right), dot(rel, up), dot(rel, forward)};
    const std::array<Vec3, 3> axes = {Vec3{right.x, up.x, forward.x} * r, Vec3{right.y, up.y, forward.y} * r,
                                      Vec3{right.z, up.z, forward.z} * r};
    PixelBounds bounds;
    for (int bits = 0; bits < 8; ++bits) {
        const Vec3 p = center + (bits & 1 ? axes[0] : -axes[0]) + (bits & 2 ? axes[1] : -axes[1]) +
                       (bits & 4 ? axes[2] : -axes[2]);
        view.widen(bounds, p.x, p.y, p.z);
    }
    bounds.in_front = true;
    return bounds;
}

TEST(SpherePixelBounds, ExtremeCornersGiveTheBoundsOfEveryCorner) {
    std::mt19937 random(23);
    std::uniform_real_distribution<double> spot(-30, 30), size(0.001, 3);
    int checked = 0;
    for (int view_index = 0; view_index < 20; ++view_index) {
        const Vec3 eye{spot(random), spot(random), spot(random)};
        const Vec3 lookat{spot(random), spot(random), spot(random)};
        const ObjectBounds view(make_frame_camera(eye, lookat, {0, 1, 0}, 20 + 7 * view_index, 1920, 1080, eye));
        for (int i = 0; i < 2000; ++i) {
            const Sphere sphere = testing::make_sphere({spot(random), spot(random), spot(random)}, size(random), {1, 1, 1});
            if (!view.box_clearly_in_front(sphere.center, sphere.radius)) continue;
            const PixelBounds expected = corner_by_corner(view, sphere);
            const PixelBounds actual = SphereKind::pixel_bounds(view, sphere, {});
            ASSERT_EQ(actual.col_min, expected.col_min) << "view " << view_index << " sphere " << i;
            ASSERT_EQ(actual.col_max, expected.col_max) << "view " << view_index << " sphere " << i;
            ASSERT_EQ(actual.row_min, expected.row_min) << "view " << view_index << " sphere " << i;
            ASSERT_EQ(actual.row_max, expected.row_max) << "view " << view_index << " sphere " << i;
            ASSERT_EQ(actual.in_front, expected.in_front);
            ASSERT_EQ(actual.whole_screen, expected.whole_screen);
            ++checked;
        }
    }
    EXPECT_GT(checked, 10000);
}

}  // namespace
}  // namespace clr
