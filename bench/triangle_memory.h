// What a scene's mesh triangles cost in device memory, for the benchmark's triangle rows:
// the kernels' ClrTriangle, their meshes' ClrMeshSurface, their corner normals, their neighbours
// on shared edges and corners where the program settles hits there, and the BVH that shadow rays
// traverse.
#pragma once

#include <cstddef>

#include "scene/scene.h"

namespace clr::bench {

struct TriangleMemory {
    std::size_t triangles = 0;
    std::size_t triangle_bytes = 0;  // triangles * sizeof(ClrTriangle)
    std::size_t mesh_bytes = 0;      // meshes * sizeof(ClrMeshSurface)
    std::size_t normal_bytes = 0;    // three cl_float4 for each triangle with corner normals
    std::size_t tie_bytes = 0;       // six ints a triangle where FeatureSet::triangle_ties is on
    std::size_t bvh_bytes = 0;       // the whole scene's BVH: nodes (ClrBvhNode) and leaf items

    // Everything above shared by the triangles (the BVH's few non-triangle objects included:
    // the triangle scenes hold a handful next to a million triangles); 0 without triangles.
    double per_triangle() const {
        const std::size_t bytes = triangle_bytes + mesh_bytes + normal_bytes + tie_bytes + bvh_bytes;
        return triangles ? static_cast<double>(bytes) / triangles : 0;
    }
};

// Builds the scene's BVH as the renderer does (render/bvh.h) to measure it.
TriangleMemory triangle_memory(const Scene& scene);

}  // namespace clr::bench
