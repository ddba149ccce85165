// The bench's bytes per triangle: the kernels' structures for each triangle, and a BVH whose
// size a binary tree over the scene's objects bounds from both sides.
#include <gtest/gtest.h>

#include "bench/bench_scenes.h"
#include "bench/triangle_memory.h"
#include "scene/triangle_ties.h"
#include "support/scene_builder.h"

namespace clr::bench {
namespace {

TEST(TriangleMemory, NothingWithoutTriangles) {
    Scene scene = make_bench_scene(find_bench_scene("course"), 192, 108);
    TriangleMemory memory = triangle_memory(scene);
    EXPECT_EQ(memory.triangles, 0u);
    EXPECT_EQ(memory.per_triangle(), 0.0);
}

TEST(TriangleMemory, TrianglesNormalsAndTree) {
    Scene scene = testing::make_scene({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60, 64, 36);
    testing::add_mesh(scene, testing::grid_mesh({-2, -2, -5}, {4, 0, 0}, {0, 4, 0}, 10, 10), {0.5, 0.5, 0.5});
    testing::add_mesh(scene, testing::sphere_mesh({0, 0, -8}, 1, 16, 8, true), {0.5, 0.5, 0.5});
    const std::size_t flat = 200, smooth = scene.triangles.size() - flat;
    ASSERT_EQ(scene.corner_normals.size(), smooth);
    const TriangleMemory memory = triangle_memory(scene);
    EXPECT_EQ(memory.triangles, flat + smooth);
    EXPECT_EQ(memory.triangle_bytes, (flat + smooth) * 64) << "one cache line a triangle";
    EXPECT_EQ(memory.mesh_bytes, 2u * 32u) << "each mesh's shading once";
    EXPECT_EQ(memory.normal_bytes, smooth * 3 * 16) << "three float4 normals for each smooth triangle only";
    EXPECT_EQ(memory.tie_bytes, 0u) << "unlit: no neighbours on the device";
    // Every triangle is in one leaf (a 4-byte item) and there is at least a root node (32
    // bytes); a binary tree over n objects has at most 2n - 1 nodes.
    const std::size_t n = flat + smooth;
    EXPECT_GE(memory.bvh_bytes, n * 4 + 32);
    EXPECT_LE(memory.bvh_bytes, n * 4 + (2 * n - 1) * 32);
    EXPECT_DOUBLE_EQ(memory.per_triangle(),
                     static_cast<double>(memory.triangle_bytes + memory.mesh_bytes + memory.normal_bytes +
                                         memory.bvh_bytes) /
                         n);
    scene.has_sun = true;  // lit, the grid faceted: six neighbour numbers a triangle
    scene.sun_location = {1, 5, 2};
    compute_triangle_ties(scene);
    EXPECT_EQ(triangle_memory(scene).tie_bytes, n * 24);
}

}  // namespace
}  // namespace clr::bench
