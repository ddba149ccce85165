/*
 * The data both sides share: the host fills these structs and the kernels read them, so each
 * struct is textually one definition. Rules that keep the layouts identical in C++ and
 * OpenCL C: only 4-byte scalars and float4-sized vectors (never float3, which is 12 bytes on
 * the host and 16 in OpenCL C), explicit padding to a multiple of 16 bytes, and a size check
 * on the host (static_assert below) and on the device (tests/device/struct_layout_test.cpp).
 */
#ifndef CLR_TYPES_H
#define CLR_TYPES_H

#ifdef __OPENCL_VERSION__
typedef float4 clr_float4;
typedef float clr_float;
typedef int clr_int;
typedef uint clr_uint;
#else
#include <CL/cl_platform.h>
typedef cl_float4 clr_float4;
typedef cl_float clr_float;
typedef cl_int clr_int;
typedef cl_uint clr_uint;
#endif

/* Surface flags (ClrSphere.flags, ClrBillboard.flags, ClrTriangle.mesh_flags, ClrMeshSurface.flags,
 * ClrPlane.flags). */
#define CLR_SURFACE_MIRROR 1u   /* ideal mirror on the front side */
#define CLR_SURFACE_TEXTURED 2u /* shows its image; otherwise its flat colour */
#define CLR_SURFACE_HOLES 4u    /* its image has texels with alpha below CLR_OPAQUE_ALPHA */
#define CLR_SURFACE_NEAR_EYE 8u /* so large for its distance from the frame's eye that the
                                   kernels may take what the host computed from the eye in double
                                   (kinds/sphere.cl, billboard.cl, triangle.cl: each says when) */

/* The only alpha at which a texel stops rays; any lower alpha is a hole that rays pass
 * through (docs/scene-format.md, Conventions: Billboards). The texels' alpha tests and the
 * coverage masks built from them (host/render/coverage_mask.h) both decide by it. */
#define CLR_OPAQUE_ALPHA 255u

/* The packet kernel reads a billboard's coverage bits (host/render/coverage_mask.h) as the
 * CLR_COVERAGE_WINDOW_WORDS words from its image's first word when they hold all of the
 * image's bits (images of up to 32x32 texels), so that many words follow the last image's. */
#define CLR_COVERAGE_WINDOW_WORDS 32u

/* Screen tiles for primary rays (host/render/screen_tiles.h): a tile is
 * kClrTileSize x kClrTileSize pixels. */
#define CLR_TILE_SIZE 16
#ifndef __OPENCL_VERSION__
constexpr int kClrTileSize = CLR_TILE_SIZE;
#endif

/* What a ray hit (ClrHit.kind): the primitive kinds, in the order that ranks equally near
 * hits (kernels/common/hit_order.cl). kernels/kinds/kinds.cl lists them. */
#define CLR_HIT_NONE 0
#define CLR_HIT_SPHERE 1
#define CLR_HIT_BILLBOARD 2
#define CLR_HIT_TRIANGLE 3
#define CLR_HIT_PLANE 4

/* A scene item, as screen-tile lists and BVH leaves store an object: its kind (CLR_HIT_*) in
 * the top CLR_ITEM_KIND_BITS bits, its index among the objects of that kind in the others
 * (kernels/common/scene_items.cl, host/render/scene_item.h). Four bits leave room for 15
 * kinds; 28 for 268 million objects of a kind, more than a scene file can describe. */
#define CLR_ITEM_KIND_BITS 4
#define CLR_ITEM_INDEX_BITS 28
#define CLR_ITEM_INDEX_MASK 0x0FFFFFFFu

/* The pinhole camera of one frame, flattened from the scene's camera
 * (docs/scene-format.md, Conventions: Camera). The direction through
 * the point (col + ox, row + oy) of pixel (col, row) (the centre: ox = oy = 0.5) is
 *   forward + (2(col+ox)/width - 1) * right + (1 - 2(row+oy)/height) * up. */
typedef struct {
    clr_float4 eye;     /* xyz = eye position; w = the near clip depth (0: none, CLR_FEATURE_CLIP) */
    clr_float4 forward; /* xyz = -w, the unit view direction (image plane at distance 1); w = the
                           far clip depth (+inf: none) */
    clr_float4 right;   /* xyz = halfW * u: from the plane's centre to its right edge */
    clr_float4 up;      /* xyz = halfH * v: from the plane's centre to its top edge */
    clr_int width;       /* image width in pixels */
    clr_int height;      /* image height in pixels */
    clr_int samples;     /* samples per pixel (anti-aliasing), >= 1 */
    clr_uint frame_seed; /* seed of this frame's sample pattern (clr_samples.h) */
} ClrCamera;

typedef struct {
    clr_float4 center_radius; /* xyz = centre, w = radius (> 0) */
    clr_float4 color;         /* xyz = ambient colour; w = the eye's power |eye - centre|^2 - r^2 */
    clr_uint flags;           /* CLR_SURFACE_* */
    clr_uint material;        /* its Blinn-Phong material in `materials` (CLR_FEATURE_LIGHTS) */
    clr_uint pad1, pad2;
} ClrSphere;

/* A parallelogram UL + a*(UR-UL) + b*(LL-UL), 0 <= a, b <= 1. */
typedef struct {
    clr_float4 corner; /* xyz = UL */
    clr_float4 normal; /* xyz = unit front normal normalize((LL-UL) x (UR-UL)); w = the plane's offset from the eye */
    clr_float4 dual_a; /* xyz = vector whose dot with (P - UL) gives a, for P in the plane */
    clr_float4 dual_b; /* xyz = vector whose dot with (P - UL) gives b, for P in the plane */
    clr_float4 color;  /* xyz = flat colour (ambient); w unused */
    clr_uint texel_offset; /* first texel of its image in the texel buffer */
    clr_int texture_width;  /* image width in texels (0 when untextured) */
    clr_int texture_height; /* image height in texels (0 when untextured) */
    clr_uint flags;         /* CLR_SURFACE_* */
} ClrBillboard;

/* A triangle of a mesh: corners c0, c1, c2 in the face's order, seen from both sides. Its
 * normal is the corner normals (triangle_normals[normals + 0..2], xyz) interpolated by the
 * hit's barycentric coordinates where the OBJ gives them, else (c1 - c0) x (c2 - c0). 64 bytes,
 * one cache line: what a ray's test reads, and no more (its mesh's colour, material and mirror
 * flag are its ClrMeshSurface, read only where a ray's hit is shaded). */
typedef struct {
    /* The corners' w hold the plane's normal (c1 - c0) x (c2 - c0) from edges scaled by a power
     * of two (host: TriangleKind::move): corner0.w, corner1.w, corner2.w = x, y, z. */
    clr_float4 corner0; /* xyz = c0; w = the plane normal's x */
    clr_float4 corner1; /* xyz = c1; w = its y */
    clr_float4 corner2; /* xyz = c2; w = its z */
    clr_float plane_offset; /* the plane's offset (c0 - eye).n, computed in double (host) */
    /* The largest |x| + |y| + |z| of its edges as stored, rounded up: what bounds its edge
     * volumes' rounding (kernels/kinds/triangle_sides.cl). */
    clr_float longest_edge;
    /* Bits 0-7: its own CLR_SURFACE_* (CLR_SURFACE_NEAR_EYE); bits 8-31: its mesh's entry in
     * mesh_surfaces (CLR_TRIANGLE_MESH_SHIFT; a scene has at most 2^24 triangles, and every
     * mesh at least one). */
    clr_uint mesh_flags;
    clr_int normals; /* first of its three corner normals in triangle_normals, or -1 */
} ClrTriangle;

#define CLR_TRIANGLE_MESH_SHIFT 8u
#define CLR_TRIANGLE_OWN_FLAGS 0xffu

/* What every triangle of one mesh shares: its shading. */
typedef struct {
    clr_float4 color;  /* xyz = the mesh's ambient colour; w unused */
    clr_uint flags;    /* CLR_SURFACE_MIRROR */
    clr_uint material; /* its Blinn-Phong material in `materials` (CLR_FEATURE_LIGHTS) */
    clr_uint pad0, pad1;
} ClrMeshSurface;

/* An infinite plane through `point` with unit normal `normal`, seen from both sides. Planes
 * are in no BVH and no screen tile: every ray tests every plane. */
typedef struct {
    clr_float4 point;  /* xyz = a point of the plane; w = the plane's offset from the eye */
    clr_float4 normal; /* xyz = unit normal as the scene gives it; w unused */
    clr_float4 color;  /* xyz = ambient colour; w unused */
    clr_uint flags;    /* CLR_SURFACE_* */
    clr_uint material; /* its Blinn-Phong material in `materials` */
    clr_uint pad0, pad1;
} ClrPlane;

/* A point light of the Blinn-Phong model (docs/scene-format.md, Lights and materials). */
typedef struct {
    clr_float4 position; /* xyz = position; w unused */
    clr_float4 color;    /* xyz = its colour (intensity per channel); w unused */
} ClrLight;

/* A Blinn-Phong material: the coefficients that multiply each light's colour, and the share
 * of the mirror ray's colour added. The ambient coefficient is the object's own colour. */
typedef struct {
    clr_float4 diffuse;  /* xyz = k_d; w = the Phong exponent p */
    clr_float4 specular; /* xyz = k_s; w unused */
    clr_float4 mirror;   /* xyz = k_m; w unused */
} ClrMaterial;

typedef struct {
    clr_float4 origin;    /* xyz = origin; w unused */
    clr_float4 direction; /* xyz = unit direction; w unused */
} ClrRay;

typedef struct {
    clr_float t;    /* distance along the (unit) ray direction; +inf when kind is NONE */
    clr_int kind;   /* CLR_HIT_* */
    clr_int index;  /* index among the objects of its kind; -1 when kind is NONE */
    clr_int pad0;
} ClrHit;

/* A node of the bounding volume hierarchy used by secondary rays (host/render/bvh.h). Trees
 * are at most CLR_BVH_STACK - 1 levels deep, so a traversal stack of CLR_BVH_STACK suffices.
 * 32 bytes, and two siblings start at an even index, so that a node's two children are one
 * 64-byte cache line (host: compile_bvh). The w words hold integers plus CLR_BVH_WORD_BIAS as
 * a float's bits: kernels read them with bvh_first() and bvh_count() (kernels/common/bvh_nodes.cl).
 * The bias (1.0f's bits) makes every such word a normal float: small integers' bits are
 * subnormal floats, and a box's float4 arithmetic, which may carry the w lane along, then took a
 * processor's slow path for subnormal operands at every node. */
#define CLR_BVH_STACK 48
#define CLR_BVH_WORD_BIAS 0x3F800000u
/* The largest integer a w word holds: with the bias, below the bits of +inf. */
#define CLR_BVH_WORD_MAX 0x3FFFFFFFu
typedef struct {
    clr_float4 lower; /* xyz = lower corner of the bounds; w = first (biased): inner node, its
                         left child (the right child is first + 1); leaf, its first item */
    clr_float4 upper; /* xyz = upper corner; w = count (biased): leaf, its number of items (scene
                         items, see CLR_ITEM_KIND_BITS); 0: inner node */
} ClrBvhNode;

/* Everything about the scene that is not per object and not per frame. */
typedef struct {
    clr_float4 background; /* xyz = background colour */
    clr_float4 sun;        /* xyz = sun position */
    clr_int sphere_count;
    clr_int billboard_count;
    clr_int max_depth; /* mirror reflections allowed along one path */
    clr_int lit;       /* 1: sun lighting (a kernel compiled without CLR_FEATURE_SUN ignores it) */
    clr_int triangle_count;
    clr_int plane_count;
    clr_int light_count; /* point lights of the Blinn-Phong model (CLR_FEATURE_LIGHTS) */
    /* 1: primary packets walk the BVH (CLR_FEATURE_BVH) instead of screen-tile lists, which
     * the host then leaves empty (packet/bvh_walk16.cl); 0: the lists */
    clr_int primary_bvh;
} ClrSceneInfo;

#ifndef __OPENCL_VERSION__
static_assert(sizeof(ClrCamera) == 80, "ClrCamera layout");
static_assert(sizeof(ClrSphere) == 48, "ClrSphere layout");
static_assert(sizeof(ClrBillboard) == 96, "ClrBillboard layout");
static_assert(sizeof(ClrRay) == 32, "ClrRay layout");
static_assert(sizeof(ClrHit) == 16, "ClrHit layout");
static_assert(sizeof(ClrTriangle) == 64, "ClrTriangle layout");
static_assert(sizeof(ClrMeshSurface) == 32, "ClrMeshSurface layout");
static_assert(sizeof(ClrSceneInfo) == 64, "ClrSceneInfo layout");
static_assert(sizeof(ClrPlane) == 64, "ClrPlane layout");
static_assert(sizeof(ClrLight) == 32, "ClrLight layout");
static_assert(sizeof(ClrMaterial) == 48, "ClrMaterial layout");
static_assert(sizeof(ClrBvhNode) == 32, "ClrBvhNode layout");
#endif

#endif /* CLR_TYPES_H */
