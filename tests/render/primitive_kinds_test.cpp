// The list of primitive kinds (host/kinds/kinds.h): its order is the hit order the kernels
// rank ties by, each kind's shading rule is the documented one (docs/scene-format.md,
// Conventions: Lighting and shadows), each kind's BVH box holds the whole object, and a
// triangle's least distance from the eye bounds its distance closely from below.
#include "kinds/kinds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "render/frame_camera.h"
#include "render/object_bounds.h"
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

// The least distance from `eye` to points of `triangle` on a fine barycentric grid: an upper
// bound on the distance of the triangle itself, close for the grid's spacing.
double sampled_distance(const Triangle& triangle, const Vec3& eye) {
    const auto& c = triangle.corners;
    double least = INFINITY;
    constexpr int kSteps = 40;
    for (int i = 0; i <= kSteps; ++i)
        for (int j = 0; i + j <= kSteps; ++j) {
            const double u = double(i) / kSteps, v = double(j) / kSteps;
            least = std::min(least, length(c[0] + (c[1] - c[0]) * u + (c[2] - c[0]) * v - eye));
        }
    return least;
}

// The screen tiles list triangles nearest first by this bound, and a row stops once its hits
// are nearer than the next one's: it must never exceed the triangle's distance, and a triangle
// seen edge on, whose plane passes through the eye however far it lies, must not bound at 0
// (a terrain seen at a low angle was then searched to the end of every list: half the speed).
TEST(PrimitiveKinds, TriangleLeastDistanceBoundsItsDistanceClosely) {
    const FrameCamera camera = make_frame_camera({0, 1, 0}, {0, 1, -10}, {0, 1, 0}, 60, 64, 48);
    const ObjectBounds view(camera);
    const Vec3 eye = camera.eye_in_scene();
    Triangle edge_on;  // in the plane y = 1, through the eye, 10 to 12 in front of it
    edge_on.corners = {Vec3{-1, 1, -10}, Vec3{1, 1, -10}, Vec3{0, 1, -12}};
    const double bound = TriangleKind::least_distance(view, edge_on, {});
    EXPECT_LE(bound, sampled_distance(edge_on, eye));
    EXPECT_GE(bound, 9.9) << "bounded by its plane, which holds the eye";

    std::mt19937 random(25);
    std::uniform_real_distribution<double> spot(-6, 6);
    for (int i = 0; i < 400; ++i) {
        Triangle t;
        const Vec3 at{spot(random), spot(random), spot(random) - 8};
        t.corners = {at, at + Vec3{spot(random), spot(random), spot(random)} * 0.3,
                     at + Vec3{spot(random), spot(random), spot(random)} * 0.3};
        const double least = TriangleKind::least_distance(view, t, {});
        EXPECT_LE(least, sampled_distance(t, eye) + 1e-12) << "triangle " << i;
        // Corners relative to an object origin (impostors): the same triangle, the same bound.
        Triangle moved = t;
        for (Vec3& corner : moved.corners) corner = corner - Vec3{1, 2, 3};
        EXPECT_NEAR(TriangleKind::least_distance(view, moved, {1, 2, 3}), least, 1e-9) << "triangle " << i;
    }
}

// The kernels weigh the host's double values against their own only for objects marked near
// the eye (CLR_SURFACE_NEAR_EYE): the ground objects far larger than their distance that need
// them (Stress.Ground*), never ordinary ones, whose every test that cost (8% of a mesh's
// primary rays).
TEST(PrimitiveKinds, OnlyObjectsFarLargerThanTheirDistanceAreMarkedNearTheEye) {
    Scene scene = testing::make_scene({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60, 32, 32);
    testing::TestMesh mesh;
    mesh.triangles = {{Vec3{-0.2, 0, 0}, Vec3{0.2, 0, 0}, Vec3{0, 0.3, 0}},     // 0.3 across, 5 away
                      {Vec3{-1e8, -1.4, -1e8}, Vec3{1e8, -1.4, -1e8}, Vec3{0, -1.4, 1e8}}};  // ground
    testing::add_mesh(scene, mesh, {1, 1, 1});
    const Vec3 eye{0, 0, 5};
    EXPECT_FALSE(TriangleKind::device(scene, scene.triangles[0], eye).mesh_flags & CLR_SURFACE_NEAR_EYE);
    EXPECT_TRUE(TriangleKind::device(scene, scene.triangles[1], eye).mesh_flags & CLR_SURFACE_NEAR_EYE);
    EXPECT_FALSE(SphereKind::device(testing::make_sphere({0, 0, 0}, 1, {1, 1, 1}), eye).flags & CLR_SURFACE_NEAR_EYE);
    EXPECT_TRUE(SphereKind::device(testing::make_sphere({0, -1e8 - 1.4, 5}, 1e8, {1, 1, 1}), eye).flags &
                CLR_SURFACE_NEAR_EYE);
    const Billboard wall = testing::make_billboard({-1, 1, 0}, {-1, -1, 0}, {1, 1, 0}, {1, 1, 1});
    EXPECT_FALSE(BillboardKind::device(wall, nullptr, eye).flags & CLR_SURFACE_NEAR_EYE);
    // 2e12 across, tilted by a twentieth about the line 1.4 under the eye.
    const Billboard ground = testing::make_billboard({-1e12, -1.4 - 5e10, -1e12}, {-1e12, -1.4 + 5e10, 1e12},
                                                     {1e12, -1.4 - 5e10, -1e12}, {1, 1, 1});
    EXPECT_TRUE(BillboardKind::device(ground, nullptr, eye).flags & CLR_SURFACE_NEAR_EYE);
    // The mark follows the eye: the same sphere seen from far away is ordinary.
    EXPECT_FALSE(SphereKind::device(testing::make_sphere({0, -1e8 - 1.4, 5}, 1e8, {1, 1, 1}), {0, 1e9, 5}).flags &
                 CLR_SURFACE_NEAR_EYE);
}

}  // namespace
}  // namespace clr
