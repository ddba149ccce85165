// The host-side signature of every kernel clrender runs, each next to the parameter list it
// mirrors in kernels/*.cl: the renderer and the stage tests bind kernels only through these
// (device/kernel_args.h), and tests/device/kernel_signatures_test.cpp checks each against the
// kernel's own parameters.
#pragma once

#include <string>
#include <vector>

#include "device/kernel_args.h"
#include "shared/clr_types.h"

namespace clr {

CLR_KERNEL_VALUE_TYPE(ClrCamera, "ClrCamera")
CLR_KERNEL_VALUE_TYPE(ClrSceneInfo, "ClrSceneInfo")

// The scene every tracing kernel reads: the parameters of CLR_SCENE_PARAMS
// (kernels/intersect.cl), in its order.
struct SceneArgs {
    cl::Buffer spheres;     // ClrSphere[info.sphere_count]
    cl::Buffer billboards;  // ClrBillboard[info.billboard_count]
    cl::Buffer triangles;   // ClrTriangle[info.triangle_count]
    cl::Buffer mesh_surfaces;     // ClrMeshSurface, one a mesh (ClrTriangle::mesh_flags)
    cl::Buffer triangle_normals;  // float4: three corner normals per triangle that has them
    cl::Buffer triangle_ties;     // int, six a triangle: Scene::triangle_ties (CLR_FEATURE_TRIANGLE_TIES)
    cl::Buffer planes;      // ClrPlane[info.plane_count]
    cl::Buffer lights;      // ClrLight[info.light_count]
    cl::Buffer materials;   // ClrMaterial: [0] the default, then each distinct material
    cl::Buffer texels;      // uchar4, every billboard image one after another
    cl::Buffer coverage;    // uint: bit k % 32 of word k / 32 is set where texel k stops rays
    ClrSceneInfo info{};
    cl::Buffer bvh_nodes;  // ClrBvhNode (read only with CLR_FEATURE_BVH)
    cl::Buffer bvh_items;  // uint object indices of the BVH's leaves

    template <typename Visit>
    void for_each_arg(Visit& visit) const {
        visit("spheres", spheres);
        visit("billboards", billboards);
        visit("triangles", triangles);
        visit("mesh_surfaces", mesh_surfaces);
        visit("triangle_normals", triangle_normals);
        visit("triangle_ties", triangle_ties);
        visit("planes", planes);
        visit("lights", lights);
        visit("materials", materials);
        visit("texels", texels);
        visit("coverage", coverage);
        visit("info", info);
        visit("bvh_nodes", bvh_nodes);
        visit("bvh_items", bvh_items);
    }
};

// One frame's screen tiles (render/screen_tiles.h), the last parameters of render_packets.
struct TileArgs {
    cl::Buffer offsets;  // uint: tile t lists items [offsets[t], offsets[t + 1])
    cl::Buffer items;    // uint scene items (render/scene_item.h)
    cl::Buffer nearest;  // float: a lower bound on each item's hit distance
    cl::Buffer rows;     // uint: the pixel rows each item may cover
    cl_int tiles_x = 0;  // tiles per row of the screen

    template <typename Visit>
    void for_each_arg(Visit& visit) const {
        visit("tile_offsets", offsets);
        visit("tile_items", items);
        visit("item_nearest", nearest);
        visit("item_rows", rows);
        visit("tiles_x", tiles_x);
    }
};

// kernels/render.cl
using RenderPacketsSignature = KernelSignature<ClrCamera, cl_int, cl_int, SceneArgs, cl::Buffer, TileArgs>;
inline const RenderPacketsSignature kRenderPackets{
    "render_packets", {"camera", "first_row", "row_count", "CLR_SCENE_PARAMS", "pixels", "screen tiles"}};
using RenderSignature = KernelSignature<ClrCamera, cl_int, cl_int, SceneArgs, cl::Buffer>;
inline const RenderSignature kRender{"render", {"camera", "first_row", "row_count", "CLR_SCENE_PARAMS", "pixels"}};

// The stage kernels, which the tests run alone (kernels/raygen.cl, intersect.cl, shade.cl).
using RaygenSignature = KernelSignature<ClrCamera, cl::Buffer>;
inline const RaygenSignature kRaygen{"raygen", {"camera", "rays"}};
using IntersectSignature = KernelSignature<cl::Buffer, cl_int, SceneArgs, cl::Buffer>;
inline const IntersectSignature kIntersect{"intersect", {"rays", "ray_count", "CLR_SCENE_PARAMS", "hits"}};
using ShadeSignature = KernelSignature<cl::Buffer, cl::Buffer, cl_int, cl_int, SceneArgs, cl::Buffer, cl::Buffer>;
inline const ShadeSignature kShade{
    "shade", {"rays", "hits", "ray_count", "reflections", "CLR_SCENE_PARAMS", "colors", "next_rays"}};

// kernels/layout.cl: the device's sizes and offsets of the shared structs.
using StructLayoutSignature = KernelSignature<cl::Buffer>;
inline const StructLayoutSignature kStructLayout{"struct_layout", {"out"}};

struct KernelDeclaration {
    std::string kernel_name;
    std::vector<KernelParam> params;
};

// Every signature above, for the test that compares them with the kernels.
std::vector<KernelDeclaration> kernel_declarations();

}  // namespace clr
