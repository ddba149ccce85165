// The list of primitive kinds (host/kinds/kinds.h): its order is the hit order the kernels
// rank ties by, each kind's shading rule is the documented one (docs/scene-format.md,
// Conventions: Lighting and shadows), and each kind's BVH box holds the whole object.
#include "kinds/kinds.h"

#include <gtest/gtest.h>

#include <vector>

#include "support/scene_builder.h"

namespace clr {
namespace {

bool inside(const Box3& box, const Vec3& p) {
    return box.lower.x <= p.x && p.x <= box.upper.x && box.lower.y <= p.y && p.y <= box.upper.y &&
           box.lower.z <= p.z && p.z <= box.upper.z;
}

TEST(PrimitiveKinds, ListedInHitOrderEachOnce) {
    std::vector<int> hits;
    for_each_kind([&](auto kind) { hits.push_back(decltype(kind)::kHit); });
    EXPECT_EQ(hits, (std::vector<int>{CLR_HIT_SPHERE, CLR_HIT_BILLBOARD, CLR_HIT_TRIANGLE, CLR_HIT_PLANE}));
    // The BVH and the screen tiles hold the bounded kinds only: planes are tested apart.
    std::vector<int> bounded;
    for_each_bounded_kind([&](auto kind) { bounded.push_back(decltype(kind)::kHit); });
    EXPECT_EQ(bounded, (std::vector<int>{CLR_HIT_SPHERE, CLR_HIT_BILLBOARD, CLR_HIT_TRIANGLE}));
}

TEST(PrimitiveKinds, SpheresAndMeshesAreLitBillboardsAreNot) {
    EXPECT_TRUE(kind_is_lit(CLR_HIT_SPHERE));
    EXPECT_TRUE(kind_is_lit(CLR_HIT_TRIANGLE));
    EXPECT_TRUE(kind_is_lit(CLR_HIT_PLANE));
    EXPECT_FALSE(kind_is_lit(CLR_HIT_BILLBOARD));
    EXPECT_FALSE(kind_is_lit(CLR_HIT_NONE));

    Scene scene = testing::make_scene({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60, 32, 32);
    scene.billboards.push_back(testing::make_billboard({-1, 1, 0}, {-1, -1, 0}, {1, 1, 0}, {1, 0, 0}));
    EXPECT_FALSE(has_lit_objects(scene)) << "billboards alone: nothing for the sun to light";
    scene.spheres.push_back(testing::make_sphere({0, 0, -2}, 1, {0, 1, 0}));
    EXPECT_TRUE(has_lit_objects(scene));
}

TEST(PrimitiveKinds, BoxesHoldTheirObjects) {
    const Vec3 shift{10, -20, 30};
    const Sphere sphere = testing::make_sphere({1, 2, 3}, 0.5, {1, 1, 1});
    Vec3 centroid;
    const Box3 sphere_box = SphereKind::box(sphere, shift, centroid);
    EXPECT_EQ(centroid, sphere.center - shift);
    for (const Vec3& d : {Vec3{0.5, 0, 0}, Vec3{0, -0.5, 0}, Vec3{0, 0, 0.5}, Vec3{-0.5, 0, 0}})
        EXPECT_TRUE(inside(sphere_box, sphere.center + d - shift));
    EXPECT_FALSE(inside(sphere_box, sphere.center + Vec3{0.6, 0, 0} - shift));

    const Billboard billboard = testing::make_billboard({0, 2, 0}, {0, 0, 1}, {3, 2, 0}, {1, 1, 1});
    const Box3 billboard_box = BillboardKind::box(billboard, shift, centroid);
    const Vec3 lower_right = billboard.upper_right + (billboard.lower_left - billboard.upper_left);
    for (const Vec3& corner : {billboard.upper_left, billboard.upper_right, billboard.lower_left, lower_right})
        EXPECT_TRUE(inside(billboard_box, corner - shift));
    EXPECT_EQ(centroid, (billboard.upper_left + lower_right) * 0.5 - shift);

    Triangle triangle;
    triangle.corners = {Vec3{0, 0, 0}, Vec3{2, 1, 0}, Vec3{-1, 3, 4}};
    const Box3 triangle_box = TriangleKind::box(triangle, shift, centroid);
    for (const Vec3& corner : triangle.corners) EXPECT_TRUE(inside(triangle_box, corner - shift));
    EXPECT_EQ(triangle_box.lower, (Vec3{-1, 0, 0} - shift));
    EXPECT_EQ(triangle_box.upper, (Vec3{2, 3, 4} - shift));
}

}  // namespace
}  // namespace clr
