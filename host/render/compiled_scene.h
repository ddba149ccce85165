// The seam between the scene model and the device: a frame's geometry flattened into the
// shared structs of kernels/shared/clr_types.h (each kind's struct made by its unit,
// host/kinds/), the texel buffer, its coverage mask and the feature set.
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "render/feature_set.h"
#include "render/page_aligned_allocator.h"
#include "render/frame_geometry.h"
#include "render/texture_slot.h"
#include "scene/scene.h"
#include "shared/clr_types.h"

namespace clr {

struct CompiledScene {
    std::vector<ClrSphere> spheres;
    std::vector<ClrBillboard> billboards;  // the frame's billboards, in FrameGeometry's order
    std::vector<ClrTriangle> triangles;    // the scene's mesh triangles
    std::vector<ClrMeshSurface> mesh_surfaces;  // Scene::meshes' shading, one a mesh
    std::vector<cl_float4> triangle_normals;  // Scene::corner_normals, three a triangle
    std::vector<ClrPlane> planes;
    std::vector<ClrLight> lights;        // the scene's point lights (positions move with the origin)
    std::vector<ClrMaterial> materials;  // Scene::materials
    // RGBA bytes of every image a billboard or view may show; page-aligned, so that a device can
    // read them where they are (Renderer keeps them as the texel buffer's host memory).
    PageAlignedVector<std::uint8_t> texels;
    // One bit per texel of `texels`, set where it stops rays (render/coverage_mask.h).
    std::vector<std::uint32_t> coverage;
    std::map<const Image*, TextureSlot> textures;  // each image's place in `texels`
    // The image each placed impostor showed when last compiled, and its slot in `textures`:
    // a frame looks the slot up only where the view changed (a lookup in a map of 30,000
    // images, 10k impostors of three views, is a walk of 15 cache misses).
    std::vector<std::pair<const Image*, const TextureSlot*>> impostor_textures;
    ClrSceneInfo info{};
    FeatureSet features;
};

// The device form of `frame`, with every image that its billboards and its scene's impostor
// views may show packed once. Positions are stored relative to `origin`: with the frame's eye
// as origin, float32 keeps full precision near the camera however far from (0, 0, 0) the scene
// lies (a scene at 1e5 would otherwise lose 1/128 of a unit to rounding).
CompiledScene compile_scene(const FrameGeometry& frame, const Vec3& origin = {});

// Brings `compiled` (made from the same scene) to `frame` as it is now, relative to `origin`:
// positions re-expressed and the placed impostors compiled anew, texels, flags and features
// left as they are. What each frame of an animation needs, without repacking images.
void compile_frame(CompiledScene& compiled, const FrameGeometry& frame, const Vec3& origin);

// What the scene's triangles take on the device: their structs, their corner normals, and their
// neighbours on shared edges where the scene's program settles hits there (--check, --stats).
std::size_t triangle_device_bytes(const Scene& scene);

}  // namespace clr
