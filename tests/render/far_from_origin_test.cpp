// A scene moved far from the origin, anywhere inside the documented coordinate range of ±1e15
// (docs/scene-format.md, Numeric ranges), renders as it does at the origin: with the
// reference, which traces relative to the eye (reference/eye_relative.h), and with the
// kernels, checked against it. Every position of the scene is a multiple of 1/8, so moved by
// up to 1e15 (where doubles are 1/8 apart) it is the same scene exactly, and the reference's
// picture must be the same bytes; in absolute coordinates, hit points up to 1/16 off picked
// other texels, shadows and reflections.
#include <gtest/gtest.h>

#include <sstream>

#include "support/image_compare.h"
#include "support/render_helpers.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

std::shared_ptr<Image> checker(int size) {
    return testing::make_image(size, size, [](int col, int row) {
        const bool dark = (col + row) % 2 == 0;
        return std::array<std::uint8_t, 4>{std::uint8_t(dark ? 40 : 230), std::uint8_t(8 * col), std::uint8_t(dark ? 200 : 30), 255};
    });
}

// A lit sphere, its shadow, a mirror, a textured billboard of 16x16 texels half a unit wide and
// an upright impostor, around `origin`; the sun and eye are within 30 units.
Scene world_at(const Vec3& origin) {
    const auto at = [&](double x, double y, double z) { return origin + Vec3{x, y, z}; };
    Scene scene = testing::make_scene(at(0.5, 1.25, 8), origin, {0, 1, 0}, 50, 160, 120);
    scene.has_sun = true;
    scene.sun_location = at(20, 30, 15);
    scene.spheres.push_back(testing::make_sphere(origin, 1, {0.9, 0.4, 0.2}));
    scene.spheres.push_back(testing::make_sphere(at(0.75, 1.5, 0.625), 0.375, {0.2, 0.9, 0.4}));
    scene.spheres.push_back(testing::make_sphere(at(-2.25, 0, 0.5), 0.75, {0, 0, 0}, true));
    scene.billboards.push_back(testing::make_billboard(at(-4, 3, -3), at(-4, -2, -3), at(4, 3, -3), {0, 0, 0}, checker(16)));
    Impostor impostor;
    impostor.center = at(2.5, 0.25, -0.5);
    impostor.width = 1;
    impostor.height = 2;
    impostor.ambient = {0.9, 0.9, 0.2};
    scene.impostors.push_back(impostor);
    return scene;
}

// Offsets of each size along several axes and diagonals; 1e15 less 64 keeps the sun (30 units
// from the origin of the world) inside the range.
std::vector<Vec3> far_offsets() {
    std::vector<Vec3> offsets;
    for (double size : {1e6, 1e9, 1e12, 1e15 - 64}) {
        offsets.push_back({size, 0, 0});
        offsets.push_back({0, -size, 0});
        offsets.push_back({size, size, -size});
        offsets.push_back({-size, size, size});
    }
    return offsets;
}

std::string describe(const Vec3& v) {
    std::ostringstream text;
    text.precision(17);
    text << "world moved by [" << v.x << ", " << v.y << ", " << v.z << "]";
    return text.str();
}

TEST(FarFromOrigin, ReferenceDrawsTheSamePictureAnywhereInRange) {
    const Image at_origin = testing::render_with_reference(world_at({0, 0, 0}));
    for (const Vec3& offset : far_offsets()) {
        const Scene moved = world_at(offset);
        ASSERT_EQ(moved.spheres[1].center - offset, Vec3(0.75, 1.5, 0.625)) << "the moved scene is exact";
        const Image image = testing::render_with_reference(moved);
        const testing::ImageComparison comparison = testing::compare_images(image, at_origin);
        EXPECT_EQ(comparison.differing, 0) << describe(offset) << ": " << comparison.first_off_edge;
        EXPECT_EQ(image.rgba, at_origin.rgba) << describe(offset) << ": byte for byte";
    }
}

// The project's usual tolerance between the kernels and the reference (Stress tests): at most
// 0.1% of the pixels differ by more than 1/255. The impostor included: the host places it
// relative to the eye (host/render/impostor_placement); in scene coordinates its corners near
// 1e15 were rounded to 1/8, and its outline moved by a pixel or so.
TEST(FarFromOrigin, KernelsMatchTheReferenceAnywhereInRange) {
    for (const Vec3& offset : far_offsets()) {
        const Scene moved = world_at(offset);
        const testing::ImageComparison comparison =
            testing::compare_images(testing::render_with_kernels(moved), testing::render_with_reference(moved));
        EXPECT_LE(comparison.differing_fraction(), 0.001)
            << describe(offset) << ": " << comparison.differing << " pixels differ; " << comparison.first_off_edge;
    }
}

}  // namespace
}  // namespace clr
