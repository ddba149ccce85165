// Mesh tree shapes kept across runs (render/mesh_tree_cache.h): a second build takes the stored
// shape with boxes made from the mesh's own triangles; a stored shape that is not a tree over
// exactly those triangles, within the depth allowed, is refused and removed; other triangles
// are another key.
#include "render/mesh_tree_cache.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "render/scene_bvh.h"
#include "render/scene_item.h"
#include "support/scene_builder.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

using testing::TempFolder;

// A scene with one smooth ball of 2304 triangles (enough for a tree of its own).
Scene ball_scene(const Vec3& centre = {0, 0, -6}) {
    Scene scene = testing::make_scene({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60, 64, 48);
    testing::add_mesh(scene, testing::sphere_mesh(centre, 1.5, 48, 24, true), {0.8, 0.2, 0.2});
    return scene;
}

// A tree of `nodes` over the ball's triangles listed in order (items as the renderer has them).
Bvh crafted(const Scene& scene, std::vector<Bvh::Node> nodes) {
    Bvh tree;
    tree.nodes = std::move(nodes);
    for (std::size_t i = 0; i < scene.meshes[0].triangle_count; ++i) tree.items.push_back(scene_item(CLR_HIT_TRIANGLE, i));
    return tree;
}

MeshTreeCache test_cache(const TempFolder& folder) { return MeshTreeCache(folder.path(), 1u << 30, 16); }

std::size_t entries(const TempFolder& folder) {
    const std::filesystem::path trees = folder.path() + "/trees";
    if (!std::filesystem::exists(trees)) return 0;
    std::size_t count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(trees)) count += entry.path().extension() == ".tree";
    return count;
}

TEST(MeshTreeCache, ASecondBuildTakesTheStoredShape) {
    TempFolder folder;
    const MeshTreeCache cache = test_cache(folder);
    const Scene scene = ball_scene();
    const MeshTrees built = build_mesh_trees(scene, &cache);
    ASSERT_EQ(built.trees.size(), 1u);
    EXPECT_EQ(entries(folder), 1u) << "the built tree's shape is stored";
    const MeshTrees again = build_mesh_trees(scene, &cache);
    ASSERT_EQ(again.trees.size(), 1u);
    const Bvh& a = built.trees[0];
    const Bvh& b = again.trees[0];
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    for (std::size_t i = 0; i < a.nodes.size(); ++i) {
        EXPECT_TRUE(a.nodes[i].first == b.nodes[i].first && a.nodes[i].count == b.nodes[i].count) << "node " << i;
        EXPECT_EQ(a.nodes[i].lower, b.nodes[i].lower) << "node " << i << ": boxes made again are the builder's";
        EXPECT_EQ(a.nodes[i].upper, b.nodes[i].upper) << "node " << i;
    }
    EXPECT_EQ(a.items, b.items);

    // What is stored is what the next build takes: here a single leaf of every triangle.
    const Bvh one_leaf = crafted(scene, {{{}, {}, 0, static_cast<std::uint32_t>(scene.triangles.size())}});
    cache.store(MeshTreeCache::key(scene, scene.meshes[0], built.max_depth), one_leaf, scene.meshes[0]);
    const MeshTrees taken = build_mesh_trees(scene, &cache);
    ASSERT_EQ(taken.trees[0].nodes.size(), 1u);
    EXPECT_EQ(taken.trees[0].nodes[0].lower, a.nodes[0].lower) << "its box made from the triangles";
    EXPECT_EQ(taken.trees[0].nodes[0].upper, a.nodes[0].upper);
}

TEST(MeshTreeCache, AShapeThatIsNoTreeOverTheTrianglesIsRefusedAndRemoved) {
    TempFolder folder;
    const MeshTreeCache cache = test_cache(folder);
    const Scene scene = ball_scene();
    const Mesh& mesh = scene.meshes[0];
    const auto n = static_cast<std::uint32_t>(mesh.triangle_count);
    const int depth = kMaxBvhDepth;
    const MeshTreeCache::Key key = MeshTreeCache::key(scene, mesh, depth);
    auto leaf = [](std::uint32_t first, std::uint32_t count) { return Bvh::Node{{}, {}, first, count}; };
    auto inner = [](std::uint32_t left) { return Bvh::Node{{}, {}, left, 0}; };
    // A chain `levels` deep: inner node k (at 2k) has a leaf of triangle k on its left and the
    // next inner node on its right; the last right child is a leaf of the other triangles.
    auto chain = [&](std::uint32_t levels) {
        std::vector<Bvh::Node> nodes;
        for (std::uint32_t k = 0; k < levels; ++k) {
            nodes.push_back(inner(2 * k + 1));
            nodes.push_back(leaf(k, 1));
        }
        nodes.push_back(leaf(levels, n - levels));
        return nodes;
    };
    cache.store(key, crafted(scene, chain(depth)), mesh);
    ASSERT_TRUE(cache.load(key, scene, mesh, depth)) << "a chain as deep as allowed is a good tree";

    struct Case {
        const char* what;
        Bvh tree;
    };
    Bvh duplicate = crafted(scene, {inner(1), leaf(0, n / 2), leaf(n / 2, n - n / 2)});
    duplicate.items[1] = duplicate.items[0];
    Bvh fewer = crafted(scene, {leaf(0, n - 1)});
    fewer.items.pop_back();
    const std::vector<Case> cases = {
        {"a child before its parent (a cycle)", crafted(scene, {inner(0), leaf(0, n), leaf(0, n)})},
        {"a child beyond the nodes", crafted(scene, {inner(1), leaf(0, n)})},
        {"a node reached twice", crafted(scene, {inner(1), inner(2), leaf(0, n / 2), leaf(n / 2, n - n / 2)})},
        {"a node no parent reaches", crafted(scene, {leaf(0, n), leaf(0, n)})},
        {"a leaf beyond the items", crafted(scene, {inner(1), leaf(0, n / 2), leaf(n / 2, n)})},
        {"a triangle in no leaf", crafted(scene, {inner(1), leaf(0, n / 2), leaf(n / 2, n / 2 - 1)})},
        {"a triangle twice", duplicate},
        {"items for fewer triangles", fewer},
        {"deeper than allowed", crafted(scene, chain(depth + 1))},
        {"no nodes", crafted(scene, {})},
    };
    for (const Case& bad : cases) {
        cache.store(key, bad.tree, mesh);
        ASSERT_EQ(entries(folder), 1u) << bad.what;
        EXPECT_FALSE(cache.load(key, scene, mesh, depth)) << bad.what;
        EXPECT_EQ(entries(folder), 0u) << bad.what << ": the entry is removed";
    }
}

TEST(MeshTreeCache, OtherTrianglesOrAnotherDepthIsAnotherKey) {
    const Scene scene = ball_scene();
    const Scene moved = ball_scene({0, 0, -6.5});
    const MeshTreeCache::Key key = MeshTreeCache::key(scene, scene.meshes[0], 40);
    EXPECT_EQ(key, MeshTreeCache::key(ball_scene(), scene.meshes[0], 40));
    EXPECT_NE(key, MeshTreeCache::key(moved, moved.meshes[0], 40));
    EXPECT_NE(key, MeshTreeCache::key(scene, scene.meshes[0], 39));
}

}  // namespace
}  // namespace clr
