// The host-built BVH: every object in exactly one leaf, boxes that contain their contents,
// small leaves, and a sensible split even when one object is far from the rest (which once
// left whole scenes in a single leaf).
#include "render/bvh.h"
#include "render/scene_bvh.h"

#include <gtest/gtest.h>

#include <sched.h>

#include <set>

#include "core/usable_cpus.h"
#include "render/scene_item.h"
#include "support/cpu_affinity.h"
#include "support/random_scene.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

bool contains(const Bvh::Node& outer, const Vec3& lower, const Vec3& upper) {
    return outer.lower.x <= lower.x && outer.lower.y <= lower.y && outer.lower.z <= lower.z &&
           outer.upper.x >= upper.x && outer.upper.y >= upper.y && outer.upper.z >= upper.z;
}

void check_structure(const Scene& scene, const Bvh& bvh) {
    ASSERT_FALSE(bvh.nodes.empty());
    std::multiset<std::uint32_t> seen;
    std::vector<std::pair<std::uint32_t, int>> stack = {{0, 0}};
    while (!stack.empty()) {
        auto [index, depth] = stack.back();
        stack.pop_back();
        const Bvh::Node& node = bvh.nodes[index];
        ASSERT_LT(depth, CLR_BVH_STACK) << "deeper than the kernels' stack";
        if (node.count == 0) {
            for (std::uint32_t child : {node.first, node.first + 1}) {
                EXPECT_TRUE(contains(node, bvh.nodes[child].lower, bvh.nodes[child].upper)) << "node " << index;
                stack.push_back({child, depth + 1});
            }
            continue;
        }
        EXPECT_LE(node.count, 4u);
        for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
            std::uint32_t item = bvh.items[k];
            seen.insert(item);
            std::uint32_t i = scene_item_index(item);
            if (scene_item_kind(item) == CLR_HIT_BILLBOARD) {
                const Billboard& b = scene.billboards[i];
                for (const Vec3& corner : {b.upper_left, b.lower_left, b.upper_right, b.upper_right + (b.lower_left - b.upper_left)})
                    EXPECT_TRUE(contains(node, corner, corner)) << "billboard " << i;
            } else {
                const Sphere& s = scene.spheres[i];
                Vec3 r{s.radius, s.radius, s.radius};
                EXPECT_TRUE(contains(node, s.center - r, s.center + r)) << "sphere " << i;
            }
        }
    }
    EXPECT_EQ(seen.size(), scene.spheres.size() + scene.billboards.size());
    EXPECT_EQ(std::set<std::uint32_t>(seen.begin(), seen.end()).size(), seen.size()) << "an object in two leaves";
}

TEST(BvhBuild, EveryObjectInOneLeafInsideItsBoxes) {
    for (std::uint32_t seed : {250u, 251u}) {
        Scene scene = testing::make_random_scene(seed, 300, 200);
        check_structure(scene, build_bvh(FrameGeometry(scene)));
    }
}

TEST(BvhBuild, AFarOutlierDoesNotStopTheSplitting) {
    Scene scene = testing::make_random_scene(252, 400, 0);
    scene.spheres.push_back(testing::make_sphere({0, -1e4, 0}, 1e4 - 12, {0.3, 0.6, 0.3}));  // a ground far below
    Bvh bvh = build_bvh(FrameGeometry(scene));
    check_structure(scene, bvh);
    EXPECT_GT(bvh.nodes.size(), 100u);
    EXPECT_EQ(bvh.nodes[0].count, 0u) << "the root must split";
}

// Subtrees of many objects are built on threads of their own and spliced in: the BVH must be
// the one a single thread builds, node for node and item for item.
TEST(BvhBuild, TheSameNodesOnOneCpuAsOnEvery) {
    if (usable_cpu_count() < 2) GTEST_SKIP() << "one usable CPU: nothing runs in parallel";
    Scene scene = testing::make_random_scene(254, 150000, 0);
    const FrameGeometry frame(scene);
    const Bvh parallel = build_bvh(frame);
    cpu_set_t every, one;
    ASSERT_EQ(::sched_getaffinity(0, sizeof(every), &every), 0);
    CPU_ZERO(&one);
    CPU_SET(testing::first_usable_cpu(), &one);
    ASSERT_EQ(::sched_setaffinity(0, sizeof(one), &one), 0);
    const Bvh serial = build_bvh(frame);
    ASSERT_EQ(::sched_setaffinity(0, sizeof(every), &every), 0);
    EXPECT_EQ(std::set<std::uint32_t>(parallel.items.begin(), parallel.items.end()).size(), scene.spheres.size());
    ASSERT_GT(serial.nodes.size(), 1000u);
    ASSERT_EQ(parallel.nodes.size(), serial.nodes.size());
    for (std::size_t i = 0; i < serial.nodes.size(); ++i) {
        const Bvh::Node& a = parallel.nodes[i];
        const Bvh::Node& b = serial.nodes[i];
        ASSERT_TRUE(a.first == b.first && a.count == b.count && a.lower == b.lower && a.upper == b.upper) << "node " << i;
    }
    EXPECT_EQ(parallel.items, serial.items);
}

TEST(BvhBuild, EmptySceneHasNoNodes) {
    Scene empty = testing::make_random_scene(253, 0, 0);
    EXPECT_TRUE(build_bvh(FrameGeometry(empty)).nodes.empty());
}

}  // namespace
}  // namespace clr
