// The frame's BVH in two levels (render/scene_bvh.h): large meshes' trees joined with the tree
// over everything else. Every object in exactly one leaf, every box around what is under it
// (relative to the BVH's origin), no path deeper than the kernels' stack; a copy of one file
// takes the first one's shape with its own bounds.
#include "render/scene_bvh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "kinds/kinds.h"
#include "render/scene_item.h"
#include "support/random_scene.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

bool contains(const Bvh::Node& node, const Vec3& p) {
    return node.lower.x <= p.x && node.lower.y <= p.y && node.lower.z <= p.z && node.upper.x >= p.x &&
           node.upper.y >= p.y && node.upper.z >= p.z;
}

// The points that must lie in a leaf holding `item`, relative to `origin`.
std::vector<Vec3> corners_of(const Scene& scene, std::uint32_t item, const Vec3& origin) {
    const std::uint32_t i = scene_item_index(item);
    switch (scene_item_kind(item)) {
    case CLR_HIT_TRIANGLE: {
        std::vector<Vec3> corners;
        for (const Vec3& corner : scene.triangles[i].corners) corners.push_back(corner - origin);
        return corners;
    }
    case CLR_HIT_SPHERE: {
        const Sphere& s = scene.spheres[i];
        const Vec3 r{s.radius, s.radius, s.radius};
        return {(s.center - origin) - r, (s.center - origin) + r};  // as SphereKind::box rounds
    }
    default:
        ADD_FAILURE() << "an item of kind " << scene_item_kind(item);
        return {};
    }
}

// Checks `bvh` over `scene`'s spheres and triangles; returns its deepest leaf's depth.
int check_structure(const Scene& scene, const Bvh& bvh) {
    EXPECT_FALSE(bvh.nodes.empty());
    std::multiset<std::uint32_t> seen;
    int deepest = 0;
    std::vector<std::pair<std::uint32_t, int>> stack = {{0, 0}};
    while (!stack.empty()) {
        auto [index, depth] = stack.back();
        stack.pop_back();
        const Bvh::Node& node = bvh.nodes.at(index);
        EXPECT_LT(depth, CLR_BVH_STACK) << "deeper than the kernels' stack";
        deepest = std::max(deepest, depth);
        if (node.count == 0) {
            for (std::uint32_t child : {node.first, node.first + 1}) {
                const Bvh::Node& inner = bvh.nodes.at(child);
                EXPECT_TRUE(contains(node, inner.lower) && contains(node, inner.upper)) << "node " << index;
                stack.push_back({child, depth + 1});
            }
            continue;
        }
        for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
            seen.insert(bvh.items.at(k));
            for (const Vec3& p : corners_of(scene, bvh.items[k], bvh.origin))
                EXPECT_TRUE(contains(node, p)) << "item " << bvh.items[k] << " outside leaf " << index;
        }
    }
    EXPECT_EQ(seen.size(), scene.spheres.size() + scene.triangles.size());
    EXPECT_EQ(std::set<std::uint32_t>(seen.begin(), seen.end()).size(), seen.size()) << "an object in two leaves";
    return deepest;
}

// Triangles along x at 1.07^k: the last bin of every split holds only the farthest one, and
// cutting it off pays, so the tree goes as deep as it may.
testing::TestMesh stretched_strip(double z, int triangles) {
    testing::TestMesh mesh;
    for (int k = 0; k < triangles; ++k) {
        const double x = std::pow(1.07, k), size = 0.1 * x;
        mesh.triangles.push_back({Vec3{x, 0, z}, Vec3{x + size, 0, z}, Vec3{x, size, z}});
    }
    return mesh;
}

Scene scene_with_meshes() {
    Scene scene = testing::make_random_scene(260, 200, 0);
    testing::TestMesh ball = testing::sphere_mesh({-4, 1, -9}, 1.5, 48, 24, true);
    testing::add_mesh(scene, ball, {0.8, 0.2, 0.2});
    scene.meshes.back().path = "ball.obj";
    // The same file placed again, moved by 8 along x: the first one's shape, refitted.
    for (auto& triangle : ball.triangles)
        for (Vec3& corner : triangle) corner = corner + Vec3{8, 0, 0};
    testing::add_mesh(scene, ball, {0.8, 0.2, 0.2});
    scene.meshes.back().path = "ball.obj";
    testing::add_mesh(scene, testing::grid_mesh({-10, -2, -20}, {20, 0, 0}, {0, 0, 15}, 40, 30), {0.5, 0.5, 0.5});
    testing::add_mesh(scene, testing::sphere_mesh({0, 4, -6}, 0.5, 8, 4, false), {0.1, 0.9, 0.1});  // small
    return scene;
}

TEST(SceneBvh, LargeMeshesGetTreesJoinedWithTheRest) {
    const Scene scene = scene_with_meshes();
    const MeshTrees meshes = build_mesh_trees(scene);
    ASSERT_EQ(meshes.trees.size(), 3u);
    EXPECT_EQ(meshes.tree_of_mesh, (std::vector<std::uint32_t>{0, 1, 2, MeshTrees::kNone}));
    for (std::uint32_t t = 0; t < 3; ++t) {
        for (std::uint32_t item : meshes.trees[t].items) {
            EXPECT_EQ(scene_item_kind(item), CLR_HIT_TRIANGLE);
            EXPECT_EQ(scene.triangles[scene_item_index(item)].mesh, t) << "a tree holds its own mesh's triangles";
        }
    }
    check_structure(scene, build_bvh(FrameGeometry(scene), meshes));
}

// A copy's tree is the first one's nodes and leaves over its own triangles; its boxes are its
// own: here the first one's moved by exactly 8 (coordinates of a few units move exactly).
TEST(SceneBvh, ACopyOfAFileTakesTheFirstOnesShape) {
    const Scene scene = scene_with_meshes();
    const MeshTrees meshes = build_mesh_trees(scene);
    const Bvh& first = meshes.trees[0];
    const Bvh& copy = meshes.trees[1];
    ASSERT_EQ(first.nodes.size(), copy.nodes.size());
    const std::size_t offset = scene.meshes[1].first_triangle - scene.meshes[0].first_triangle;
    for (std::size_t i = 0; i < first.nodes.size(); ++i) {
        const Bvh::Node& a = first.nodes[i];
        const Bvh::Node& b = copy.nodes[i];
        ASSERT_TRUE(a.first == b.first && a.count == b.count) << "node " << i;
        EXPECT_EQ(b.lower, (a.lower + Vec3{8, 0, 0})) << "node " << i;
        EXPECT_EQ(b.upper, (a.upper + Vec3{8, 0, 0})) << "node " << i;
    }
    for (std::size_t k = 0; k < first.items.size(); ++k)
        EXPECT_EQ(scene_item_index(copy.items[k]), scene_item_index(first.items[k]) + offset);
}

// Relative to another origin (the eye impostors were placed for), the mesh trees' boxes are
// moved with it and still hold their triangles.
TEST(SceneBvh, TheJoinedTreeIsRelativeToTheFramesOrigin) {
    const Scene scene = scene_with_meshes();
    FrameGeometry frame(scene);
    frame.place_impostors({{3.25, -1.5, 7}, {0, 0, 0}});
    const Bvh bvh = build_bvh(frame, build_mesh_trees(scene));
    EXPECT_EQ(bvh.origin, (Vec3{3.25, -1.5, 7}));
    check_structure(scene, bvh);
}

// Trees as deep as the builder goes, under the levels that join them: still within the
// kernels' stack.
TEST(SceneBvh, DeepMeshTreesAndTheJoinFitTheStack) {
    Scene scene = testing::make_random_scene(261, 50, 0);
    for (int m = 0; m < 5; ++m) testing::add_mesh(scene, stretched_strip(-5.0 * m, 1500), {0.5, 0.5, 0.5});
    const MeshTrees meshes = build_mesh_trees(scene);
    ASSERT_EQ(meshes.trees.size(), 5u);
    EXPECT_EQ(meshes.max_depth, kMaxBvhDepth - 3) << "six trees take three levels to join";
    const int deepest = check_structure(scene, build_bvh(FrameGeometry(scene), meshes));
    EXPECT_GE(deepest, kMaxBvhDepth - 1) << "the strips should reach the depth limit";
}

}  // namespace
}  // namespace clr
