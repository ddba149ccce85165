// The frame's BVH (render/bvh.h) in two levels. Each large mesh has a tree of its own over its
// triangles, in scene coordinates, made once per scene (and kept across runs by
// render/mesh_tree_cache.h): moving the camera, or impostors turning, never rebuilds it. A mesh placed again from the same file takes the first one's
// tree shape with its own bounds (a refit: one pass over its triangles, not a build). Each
// frame, a tree over the rest (spheres, billboards, placed impostors, small meshes' triangles)
// is joined with the mesh trees under a few nodes into one array, which the kernels walk as
// before. The tree's shape never changes an image: hits are ranked by (t, kind, index)
// whatever order the walk visits them in (kernels/common/hit_order.cl).
#pragma once

#include <cstdint>
#include <vector>

#include "render/bvh.h"
#include "render/frame_geometry.h"
#include "render/mesh_tree_cache.h"

namespace clr {

// Meshes of at least this many triangles get a tree of their own; smaller ones join the
// frame's tree, where a few triangles cost less than a tree's extra nodes.
constexpr std::size_t kOwnTreeTriangles = 1024;

struct MeshTrees {
    static constexpr std::uint32_t kNone = ~0u;
    std::vector<Bvh> trees;                 // bounds relative to (0, 0, 0)
    std::vector<std::uint32_t> tree_of_mesh;  // per Scene::meshes: an index into `trees`, or kNone
    int max_depth = kMaxBvhDepth;           // of each tree, and of the frame's own: the levels
                                            // that join them still fit the kernels' stack
};

// The scene's mesh trees (none for a scene without large meshes); with a `cache`, the trees of
// large meshes are taken from it when it holds them, and stored in it when built.
MeshTrees build_mesh_trees(const Scene& scene, const MeshTreeCache* cache = nullptr);

// Makes the boxes of `tree`, whose leaves hold triangles of `scene`, from the triangles up.
void make_boxes(Bvh& tree, const Scene& scene);

// The frame's BVH, bounds relative to frame.impostor_origin(): a tree over the frame's objects
// outside `meshes`, joined with the trees of `meshes` (built for frame.scene()). Without mesh
// trees it is the frame's tree alone.
Bvh build_bvh(const FrameGeometry& frame, const MeshTrees& meshes);

// The same with the mesh trees built here (one frame: tests and the benchmark's memory figures).
Bvh build_bvh(const FrameGeometry& frame);

}  // namespace clr
