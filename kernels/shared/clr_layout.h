/*
 * Every struct of kernels/shared/clr_types.h and every one of its fields, pads included, in
 * declaration order: the one list from which the device (kernels/layout.cl) and the host
 * (tests/device/struct_layout_test.cpp) each write out sizes and offsets, so that the two
 * compare entry by entry. A test parses clr_types.h and fails when a struct or field is
 * missing here.
 *
 * To expand it, define CLR_LAYOUT_STRUCT(type) and CLR_LAYOUT_FIELD(type, field), then write
 * CLR_LAYOUT_LIST; each struct's entry comes before its fields'.
 */
#ifndef CLR_LAYOUT_H
#define CLR_LAYOUT_H

#define CLR_LAYOUT_LIST                             \
    CLR_LAYOUT_STRUCT(ClrCamera)                    \
    CLR_LAYOUT_FIELD(ClrCamera, eye)                \
    CLR_LAYOUT_FIELD(ClrCamera, forward)            \
    CLR_LAYOUT_FIELD(ClrCamera, right)              \
    CLR_LAYOUT_FIELD(ClrCamera, up)                 \
    CLR_LAYOUT_FIELD(ClrCamera, width)              \
    CLR_LAYOUT_FIELD(ClrCamera, height)             \
    CLR_LAYOUT_FIELD(ClrCamera, samples)            \
    CLR_LAYOUT_FIELD(ClrCamera, frame_seed)         \
    CLR_LAYOUT_STRUCT(ClrSphere)                    \
    CLR_LAYOUT_FIELD(ClrSphere, center_radius)      \
    CLR_LAYOUT_FIELD(ClrSphere, color)              \
    CLR_LAYOUT_FIELD(ClrSphere, flags)              \
    CLR_LAYOUT_FIELD(ClrSphere, material)           \
    CLR_LAYOUT_FIELD(ClrSphere, pad1)               \
    CLR_LAYOUT_FIELD(ClrSphere, pad2)               \
    CLR_LAYOUT_STRUCT(ClrBillboard)                 \
    CLR_LAYOUT_FIELD(ClrBillboard, corner)          \
    CLR_LAYOUT_FIELD(ClrBillboard, normal)          \
    CLR_LAYOUT_FIELD(ClrBillboard, dual_a)          \
    CLR_LAYOUT_FIELD(ClrBillboard, dual_b)          \
    CLR_LAYOUT_FIELD(ClrBillboard, color)           \
    CLR_LAYOUT_FIELD(ClrBillboard, texel_offset)    \
    CLR_LAYOUT_FIELD(ClrBillboard, texture_width)   \
    CLR_LAYOUT_FIELD(ClrBillboard, texture_height)  \
    CLR_LAYOUT_FIELD(ClrBillboard, flags)           \
    CLR_LAYOUT_STRUCT(ClrTriangle)                  \
    CLR_LAYOUT_FIELD(ClrTriangle, corner0)          \
    CLR_LAYOUT_FIELD(ClrTriangle, corner1)          \
    CLR_LAYOUT_FIELD(ClrTriangle, corner2)          \
    CLR_LAYOUT_FIELD(ClrTriangle, plane_offset)     \
    CLR_LAYOUT_FIELD(ClrTriangle, longest_edge)     \
    CLR_LAYOUT_FIELD(ClrTriangle, mesh_flags)       \
    CLR_LAYOUT_FIELD(ClrTriangle, normals)          \
    CLR_LAYOUT_STRUCT(ClrMeshSurface)               \
    CLR_LAYOUT_FIELD(ClrMeshSurface, color)         \
    CLR_LAYOUT_FIELD(ClrMeshSurface, flags)         \
    CLR_LAYOUT_FIELD(ClrMeshSurface, material)      \
    CLR_LAYOUT_FIELD(ClrMeshSurface, pad0)          \
    CLR_LAYOUT_FIELD(ClrMeshSurface, pad1)          \
    CLR_LAYOUT_STRUCT(ClrPlane)                     \
    CLR_LAYOUT_FIELD(ClrPlane, point)               \
    CLR_LAYOUT_FIELD(ClrPlane, normal)              \
    CLR_LAYOUT_FIELD(ClrPlane, color)               \
    CLR_LAYOUT_FIELD(ClrPlane, flags)               \
    CLR_LAYOUT_FIELD(ClrPlane, material)            \
    CLR_LAYOUT_FIELD(ClrPlane, pad0)                \
    CLR_LAYOUT_FIELD(ClrPlane, pad1)                \
    CLR_LAYOUT_STRUCT(ClrLight)                     \
    CLR_LAYOUT_FIELD(ClrLight, position)            \
    CLR_LAYOUT_FIELD(ClrLight, color)               \
    CLR_LAYOUT_STRUCT(ClrMaterial)                  \
    CLR_LAYOUT_FIELD(ClrMaterial, diffuse)          \
    CLR_LAYOUT_FIELD(ClrMaterial, specular)         \
    CLR_LAYOUT_FIELD(ClrMaterial, mirror)           \
    CLR_LAYOUT_STRUCT(ClrRay)                       \
    CLR_LAYOUT_FIELD(ClrRay, origin)                \
    CLR_LAYOUT_FIELD(ClrRay, direction)             \
    CLR_LAYOUT_STRUCT(ClrHit)                       \
    CLR_LAYOUT_FIELD(ClrHit, t)                     \
    CLR_LAYOUT_FIELD(ClrHit, kind)                  \
    CLR_LAYOUT_FIELD(ClrHit, index)                 \
    CLR_LAYOUT_FIELD(ClrHit, pad0)                  \
    CLR_LAYOUT_STRUCT(ClrBvhNode)                   \
    CLR_LAYOUT_FIELD(ClrBvhNode, lower)             \
    CLR_LAYOUT_FIELD(ClrBvhNode, upper)             \
    CLR_LAYOUT_STRUCT(ClrSceneInfo)                 \
    CLR_LAYOUT_FIELD(ClrSceneInfo, background)      \
    CLR_LAYOUT_FIELD(ClrSceneInfo, sun)             \
    CLR_LAYOUT_FIELD(ClrSceneInfo, sphere_count)    \
    CLR_LAYOUT_FIELD(ClrSceneInfo, billboard_count) \
    CLR_LAYOUT_FIELD(ClrSceneInfo, max_depth)       \
    CLR_LAYOUT_FIELD(ClrSceneInfo, lit)             \
    CLR_LAYOUT_FIELD(ClrSceneInfo, triangle_count)  \
    CLR_LAYOUT_FIELD(ClrSceneInfo, plane_count)     \
    CLR_LAYOUT_FIELD(ClrSceneInfo, light_count)     \
    CLR_LAYOUT_FIELD(ClrSceneInfo, primary_bvh)

#endif /* CLR_LAYOUT_H */
