// The BVH's device form (compile_bvh, render/bvh.h): 32-byte nodes whose w words hold the
// integers, siblings at even indices so that a node's children share a cache line. Walked from
// the root beside the host tree, it is the same tree: the same leaves in the same order, boxes
// rounded outwards around the host's, and the nodes added for the pairs' parity named by none.
#include "render/bvh.h"
#include "render/scene_bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>
#include <vector>

#include "support/random_scene.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

// The integer a w word holds, and whether the word is a normal float (a subnormal one would
// slow the kernels' box arithmetic).
std::uint32_t word_value(float word) {
    EXPECT_TRUE(std::isnormal(word)) << word;
    std::uint32_t bits;
    std::memcpy(&bits, &word, sizeof bits);
    return bits - CLR_BVH_WORD_BIAS;
}

// Spheres, two large meshes (trees of their own, joined at varying parities) and a small one.
Scene scene_with_meshes() {
    Scene scene = testing::make_random_scene(262, 150, 0);
    testing::add_mesh(scene, testing::sphere_mesh({-4, 1, -9}, 1.5, 48, 24, true), {0.8, 0.2, 0.2});
    testing::add_mesh(scene, testing::grid_mesh({-10, -2, -20}, {20, 0, 0}, {0, 0, 15}, 40, 30), {0.5, 0.5, 0.5});
    testing::add_mesh(scene, testing::sphere_mesh({0, 4, -6}, 0.5, 8, 4, false), {0.1, 0.9, 0.1});
    return scene;
}

TEST(DeviceBvh, TheSameTreeWithSiblingsAtEvenIndices) {
    const Scene scene = scene_with_meshes();
    FrameGeometry frame(scene);
    const Bvh bvh = build_bvh(frame, build_mesh_trees(scene));
    const Vec3 origin{0.5, -2.25, 3};
    std::vector<ClrBvhNode> nodes;
    compile_bvh(bvh, origin, nodes);
    ASSERT_GT(nodes.size(), bvh.nodes.size()) << "the root's children start at 1, so one node at least is added";

    std::vector<bool> named(nodes.size(), false);
    std::size_t reached = 0;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> stack = {{0, 0}};  // (device, host)
    while (!stack.empty()) {
        const auto [at, host_at] = stack.back();
        stack.pop_back();
        ASSERT_LT(at, nodes.size());
        ++reached;
        const ClrBvhNode& node = nodes[at];
        const Bvh::Node& host = bvh.nodes.at(host_at);
        const Vec3 lower = host.lower - (origin - bvh.origin), upper = host.upper - (origin - bvh.origin);
        EXPECT_TRUE(node.lower.s[0] <= lower.x && node.lower.s[1] <= lower.y && node.lower.s[2] <= lower.z)
            << "node " << at;
        EXPECT_TRUE(node.upper.s[0] >= upper.x && node.upper.s[1] >= upper.y && node.upper.s[2] >= upper.z)
            << "node " << at;
        const std::uint32_t first = word_value(node.lower.s[3]), count = word_value(node.upper.s[3]);
        ASSERT_EQ(count, host.count) << "node " << at;
        if (count > 0) {
            EXPECT_EQ(first, host.first) << "a leaf's items are the host's";
            continue;
        }
        ASSERT_EQ(first % 2, 0u) << "node " << at << "'s children start at an odd index";
        named[first] = named[first + 1] = true;
        stack.push_back({first + 1, host.first + 1});
        stack.push_back({first, host.first});
    }
    EXPECT_EQ(reached, bvh.nodes.size());
    for (std::size_t i = 1; i < nodes.size(); ++i) {
        if (named[i]) continue;
        EXPECT_EQ(word_value(nodes[i].upper.s[3]), 0u) << "an added node " << i << " is zero";
        EXPECT_EQ(word_value(nodes[i].lower.s[3]), 0u) << "an added node " << i << " is zero";
    }
    EXPECT_EQ(nodes.size() - reached, static_cast<std::size_t>(std::count(named.begin() + 1, named.end(), false)));
}

TEST(DeviceBvh, AnEmptySceneHasNoNodes) {
    std::vector<ClrBvhNode> nodes(3);
    compile_bvh(Bvh{}, Vec3{}, nodes);
    EXPECT_TRUE(nodes.empty());
}

}  // namespace
}  // namespace clr
