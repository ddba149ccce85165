/* Primary rays 16 at a time: the 16 pixels of one row of a screen tile share the eye as
 * origin and the tile's object list, so each object is tested against all 16 rays with
 * 16-wide vector arithmetic (one AVX-512 instruction per operation on CPUs). PoCL does not
 * vectorise the scalar loop by itself (the running nearest hit defeats it), hence explicit
 * float16. Every formula is the scalar one of its kind (kinds/), operation for operation, so each
 * lane computes the same bits as the scalar path would (FP_CONTRACT is off, see math.cl). */
#ifndef CLR_PACKET_INTERSECT_PACKET_CL
#define CLR_PACKET_INTERSECT_PACKET_CL

#include "common/hit_order.cl"
#include "common/math.cl"
#include "common/scene_items.cl"
#include "common/scene_params.cl"
#include "intersect.cl"
#include "kinds/kinds.cl"
#include "packet/bvh_walk16.cl"
#include "packet/keep_nearer16.cl"
#include "packet/lane_masks.cl"
#include "packet/packet_types.cl"
#include "packet/shading_modes.cl"
#include "packet/texels16.cl"
#include "raygen.cl"
#include "shared/clr_types.h"

/* camera_ray_through() for the lanes' pixels, at offsets (ox, oy) in them. */
CLR_PACKET_INLINE Directions16 camera_rays16(ClrCamera camera, LanePixels16 pixels, float16 ox, float16 oy)
{
    real16 sx = 2.0f * (convert_real16(pixels.col) + convert_real16(ox)) / (real)camera.width - 1.0f;
    real16 sy = 1.0f - 2.0f * (convert_real16(pixels.row) + convert_real16(oy)) / (real)camera.height;
    real3 forward = convert_real3(camera.forward.xyz), right = convert_real3(camera.right.xyz);
    real3 up = convert_real3(camera.up.xyz);
    Directions16 d;
    d.x = forward.x + sx * right.x + sy * up.x; /* as camera_ray_through() */
    d.y = forward.y + sx * right.y + sy * up.y;
    d.z = forward.z + sx * right.z + sy * up.z;
    real16 length = sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    d.x = d.x / length;
    d.y = d.y / length;
    d.z = d.z / length;
    return d;
}

/* The nearest hits of 16 primary rays among the objects binned to their screen tile, skipping
 * those whose pixel rows leave out this `row`. The loop ends once every lane's hit is nearer
 * than every object left (the tile's items come nearest first). Where the host chose to walk
 * the BVH instead (info.primary_bvh), the tile holds no list and the same objects are found
 * there (packet/bvh_walk16.cl). Hits are ranked by
 * hits_beat16() (common/hit_order.cl), so the visiting order does not matter and the answer
 * is intersect_scene()'s, ties included. Without mirrors (CLR_LOOP_COLORS), *colors receives
 * each lane's colour as flat shading gives it: the background or kind_flat_colors16(); with a
 * sun, lanes on lit kinds still need shade_hit(). */
CLR_PACKET_INLINE void intersect_tile16(real3 origin, Directions16 d, int row, TileItems tile, CLR_SCENE_PARAMS,
                                        Hits16* best, Colors16* colors)
{
    best->t = (real16)(INFINITY);
    best->kind = (int16)(CLR_HIT_NONE);
    best->index = (int16)(-1);
#if CLR_LOOP_COLORS
    colors->r = (float16)(info.background.x);
    colors->g = (float16)(info.background.y);
    colors->b = (float16)(info.background.z);
#endif
#if CLR_LOOP_COLORS && CLR_FEATURE_ALPHA
    uint16 best_texel = (uint16)(CLR_NO_TEXEL); /* each lane's winning texel, read after the loop */
#else
    uint16 best_texel = (uint16)(0u); /* not read */
#endif
#if CLR_FEATURE_BVH
    if (info.primary_bvh)
        nearest_in_bvh16(origin, d, tile.entries, best, colors, &best_texel, CLR_SCENE_ARGS);
    else
#endif
    for (uint k = tile.first; k < tile.end; ++k) {
        if (all_lanes16(best->t < tile.nearest[k]))
            break;
        uint rows = tile.rows[k]; /* first << 16 | last pixel row the object may cover */
        if ((uint)row < (rows >> 16) || (uint)row > (rows & 0xffffu))
            continue;
        int kind = item_kind(tile.items[k]);
        int index = item_index(tile.items[k]);
#if CLR_FEATURE_ALPHA
        if (k + 2 < tile.end) /* what the test two items on reads: a billboard's coverage bits */
            prefetch_item(tile.items[k + 2], CLR_SCENE_ARGS);
#endif
        keep_nearer16(kind, index, origin, d, best, colors, &best_texel, CLR_SCENE_ARGS);
    }
#if CLR_FEATURE_PLANES
    /* Planes are in no tile (kinds/plane.cl): every packet tests each. */
    for (int i = 0; i < info.plane_count; ++i)
        keep_nearer16(CLR_HIT_PLANE, i, origin, d, best, colors, &best_texel, CLR_SCENE_ARGS);
#endif
#if CLR_LOOP_COLORS && CLR_FEATURE_ALPHA
    take_texel_colors16(best_texel, texels, colors);
#endif
}

#if CLR_FEATURE_CLIP
/* intersect_tile16() for rays that see only the depths the camera keeps (clip_segment()):
 * each lane searches the tile's objects and the planes from its own point on the near plane,
 * up to the far one, as nearest_in_view() does with every object; hits' t are the eye's. */
CLR_PACKET_INLINE void clipped_hits16(ClrCamera camera, real3 eye, Directions16 d, int row, TileItems tile,
                                      Hits16* best, CLR_SCENE_PARAMS)
{
    real xs[16], ys[16], zs[16], ts[16];
    int kinds[16], indices[16];
    vstore16(d.x, 0, xs);
    vstore16(d.y, 0, ys);
    vstore16(d.z, 0, zs);
    for (int lane = 0; lane < 16; ++lane) {
        real3 direction = (real3)(xs[lane], ys[lane], zs[lane]);
        real t_start, t_end;
        clip_segment(camera, direction, &t_start, &t_end);
        real3 origin = eye + t_start * direction;
        Hit hit;
        hit.t = t_end - t_start;
        hit.kind = CLR_HIT_NONE;
        hit.index = -1;
        for (uint k = tile.first; k < tile.end; ++k) {
            uint rows = tile.rows[k];
            if ((uint)row < (rows >> 16) || (uint)row > (rows & 0xffffu))
                continue;
            int kind = item_kind(tile.items[k]);
            int index = item_index(tile.items[k]);
            real t = kind_hit_distance(kind, index, origin, direction, INFINITY, CLR_SCENE_ARGS);
            if (hit_beats(t, kind, index, hit)) {
                hit.t = t;
                hit.kind = kind;
                hit.index = index;
            }
        }
        nearest_plane(origin, direction, CLR_HIT_NONE, -1, &hit, CLR_SCENE_ARGS);
        ts[lane] = hit.kind == CLR_HIT_NONE ? INFINITY : hit.t + t_start;
        kinds[lane] = hit.kind;
        indices[lane] = hit.index;
    }
    best->t = vload16(0, ts);
    best->kind = vload16(0, kinds);
    best->index = vload16(0, indices);
}
#endif

#endif /* CLR_PACKET_INTERSECT_PACKET_CL */
