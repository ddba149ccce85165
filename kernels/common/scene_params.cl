/* The scene buffers every stage reads, as kernel and function parameters: a function that
 * looks at the scene takes CLR_SCENE_PARAMS and passes CLR_SCENE_ARGS on. Counts stay
 * run-time values (ClrSceneInfo), so one compiled program serves every scene of a kind. The
 * host binds them in this order (SceneArgs, render/kernel_signatures.h). `coverage` holds one
 * bit per texel, set where the texel stops rays (host/render/coverage_mask.h); only the
 * packet kernel reads it, and only with CLR_FEATURE_ALPHA. */
#ifndef CLR_COMMON_SCENE_PARAMS_CL
#define CLR_COMMON_SCENE_PARAMS_CL

#include "shared/clr_types.h"

#define CLR_SCENE_PARAMS                                                                      \
    __global const ClrSphere *spheres, __global const ClrBillboard *billboards,              \
        __global const ClrTriangle *triangles, __global const ClrMeshSurface *mesh_surfaces,  \
        __global const float4 *triangle_normals,                                              \
        __global const int *triangle_ties,                                                    \
        __global const ClrPlane *planes, __global const ClrLight *lights,                    \
        __global const ClrMaterial *materials, __global const uchar4 *texels,                \
        __global const uint *coverage, ClrSceneInfo info, __global const ClrBvhNode *bvh_nodes, \
        __global const uint *bvh_items
#define CLR_SCENE_ARGS                                                                              \
    spheres, billboards, triangles, mesh_surfaces, triangle_normals, triangle_ties, planes, lights, materials, texels, coverage, info, \
        bvh_nodes, bvh_items

#endif /* CLR_COMMON_SCENE_PARAMS_CL */
