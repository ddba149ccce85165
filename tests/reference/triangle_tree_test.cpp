// The reference's index over mesh triangles (reference/triangle_tree.h) changes nothing the
// reference answers: the nearest hit of random rays, from inside and outside a mesh, with and
// without the index, is the same surface at the same distance, ties included; and a ray
// meets a triangle its index holds however it grazes the triangle's box.
#include "reference/triangle_tree.h"

#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "reference/geometry.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

Scene meshes_scene() {
    Scene scene = testing::make_scene({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60, 8, 8);
    testing::add_mesh(scene, testing::sphere_mesh({0.3, -0.2, 0.1}, 1.5, 24, 12, true), {1, 0, 0});
    testing::add_mesh(scene, testing::grid_mesh({-4, -2, 3}, {8, 0, 0}, {0, 0, -8}, 16, 16), {0, 1, 0});
    // Two coincident copies of one triangle: equal distances, which the lower index wins.
    testing::TestMesh twins;
    twins.triangles.push_back({Vec3{-1, 2, 0}, Vec3{1, 2, 0}, Vec3{0, 3, 0}});
    twins.triangles.push_back({Vec3{-1, 2, 0}, Vec3{1, 2, 0}, Vec3{0, 3, 0}});
    testing::add_mesh(scene, twins, {0, 0, 1});
    return scene;
}

TEST(TriangleTree, NearestHitsAreThoseOfTestingEveryTriangle) {
    const Scene plain = meshes_scene();
    Scene indexed = plain;
    indexed.triangle_tree = std::make_shared<const reference::TriangleTree>(indexed.triangles);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> spread(-4, 4);
    int hits = 0, twins = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 origin = i % 2 ? Vec3{spread(random), spread(random), spread(random)} : Vec3{0, 0.2, 0};
        const Vec3 target = i % 5 == 0 ? Vec3{spread(random) * 0.25, 2.5, 0} : Vec3{spread(random), spread(random), spread(random)};
        if (target == origin) continue;
        const reference::Ray ray{origin, normalize(target - origin)};
        const reference::Hit expected = reference::intersect(plain, ray);
        const reference::Hit actual = reference::intersect(indexed, ray);
        ASSERT_EQ(static_cast<int>(actual.kind), static_cast<int>(expected.kind)) << "ray " << i;
        ASSERT_EQ(actual.index, expected.index) << "ray " << i;
        ASSERT_EQ(actual.t, expected.t) << "ray " << i;
        hits += expected.kind != reference::HitKind::None;
        twins += expected.index == static_cast<int>(plain.triangles.size()) - 2;
    }
    EXPECT_GT(hits, 5000);
    EXPECT_GT(twins, 50) << "rays must reach the coincident pair";
}

// Rays along the faces of an axis-aligned quad's box (the box is flat: zero thickness in z),
// parallel to two axes: the index must still hand them the quad.
TEST(TriangleTree, RaysParallelToAFlatBoxStillReachIt) {
    Scene scene = testing::make_scene({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60, 8, 8);
    testing::add_mesh(scene, testing::grid_mesh({-1, -1, 0}, {2, 0, 0}, {0, 2, 0}, 1, 1), {1, 1, 1});
    scene.triangle_tree = std::make_shared<const reference::TriangleTree>(scene.triangles);
    for (const Vec3& origin : {Vec3{0.25, 0.5, 3}, Vec3{-1, -1, 1}, Vec3{1, 1, 7}})
        EXPECT_EQ(reference::intersect(scene, {origin, {0, 0, -1}}).kind, reference::HitKind::Triangle);
    EXPECT_EQ(reference::intersect(scene, {{1.5, 0, 3}, {0, 0, -1}}).kind, reference::HitKind::None);
}

}  // namespace
}  // namespace clr
