#include "bench/triangle_memory.h"

#include "render/bvh.h"
#include "render/feature_set.h"
#include "render/scene_bvh.h"
#include "render/frame_geometry.h"
#include "shared/clr_types.h"

namespace clr::bench {

TriangleMemory triangle_memory(const Scene& scene) {
    TriangleMemory memory;
    memory.triangles = scene.triangles.size();
    if (memory.triangles == 0) return memory;
    memory.triangle_bytes = memory.triangles * sizeof(ClrTriangle);
    memory.mesh_bytes = scene.meshes.size() * sizeof(ClrMeshSurface);
    memory.normal_bytes = scene.corner_normals.size() * 3 * sizeof(cl_float4);
    if (FeatureSet::of(scene).triangle_ties) memory.tie_bytes = memory.triangles * 6 * sizeof(cl_int);
    FrameGeometry frame(scene);
    frame.place_impostors(scene.camera_path.front());
    const Bvh bvh = build_bvh(frame);
    memory.bvh_bytes = bvh.nodes.size() * sizeof(ClrBvhNode) + bvh.items.size() * sizeof(std::uint32_t);
    return memory;
}

}  // namespace clr::bench
