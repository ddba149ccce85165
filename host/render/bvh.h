// A bounding volume hierarchy over a frame's objects, for the rays that screen tiles cannot
// cull: shadow rays and mirror reflections. Built on the host (binned surface-area heuristic,
// render/scene_bvh.h says over what and when); its bounds are re-expressed relative to each
// frame's origin when uploaded, like the rest of the geometry (see compile_scene).
#pragma once

#include <cstdint>
#include <vector>

#include "core/box3.h"
#include "core/vec3.h"
#include "shared/clr_types.h"

namespace clr {

// Deepest leaf; the kernels' traversal stack (CLR_BVH_STACK) holds one entry per level.
constexpr int kMaxBvhDepth = CLR_BVH_STACK - 1;

struct Bvh {
    struct Node {
        Vec3 lower, upper;        // bounds, relative to the Bvh's origin
        std::uint32_t first = 0;  // inner: index of the left child (the right one follows it);
                                  // leaf: first entry in `items`
        std::uint32_t count = 0;  // leaf: number of items; 0 for an inner node
    };
    std::vector<Node> nodes;          // nodes[0] is the root (absent for an empty scene)
    std::vector<std::uint32_t> items;  // scene items (render/scene_item.h)
    // What the bounds are relative to: the frame's impostor_origin(), so that placed impostors
    // (relative to their eye) are bounded exactly; (0, 0, 0) for a scene without them.
    Vec3 origin;
};

// What build_tree() bounds: a scene item (render/scene_item.h), its box and the box's centre.
struct BvhPrimitive {
    Box3 box;
    Vec3 centroid;
    std::uint32_t item;
};

// Binned SAH over `primitives`, no deeper than `max_depth` (at most kMaxBvhDepth). The nodes are
// laid out depth first, each node before its children. The frame's BVH is made of such trees
// (render/scene_bvh.h).
Bvh build_tree(std::vector<BvhPrimitive> primitives, int max_depth = kMaxBvhDepth);

// The device form into `nodes` (whose storage a moving camera's frames reuse), bounds relative
// to `origin` and rounded outwards to float so that they still contain every object after
// rounding. Node 0 is the root; siblings start at even indices (ClrBvhNode), so there may be
// a few more nodes than in `bvh`, which no node names.
void compile_bvh(const Bvh& bvh, const Vec3& origin, std::vector<ClrBvhNode>& nodes);

}  // namespace clr
