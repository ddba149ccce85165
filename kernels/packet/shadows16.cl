/* The shadow rays of 16 lanes through the BVH together (CLR_SUN_PACKETS, shading_modes.cl).
 * A lane's shadow ray towards the sun starts at its own hit point, but the 16 rays of a row
 * leave neighbouring points in one direction: they enter mostly the same boxes. Walking the
 * BVH once for the packet, each box tested for all 16 lanes in vector operations, replaces 16
 * walks of one ray each (the largest part of a sunlit mesh's frame).
 *
 * Each lane's answer is occluded()'s: a lane stops at the first surface, other than the one
 * it leaves, that hit_beats() its ray's t_max, found by the same kind_hit_distance() on the
 * same ray (for a leaf's triangles, spheres and billboards, triangle_distance16_from() and its
 * like on the 16 lanes at once, the same operations lane by lane; other kinds lane by lane). The
 * packet only decides which leaves are visited, and it visits every leaf that
 * any lane's own walk would (a box test in vectors rounds otherwise than box_reachable(), by
 * far less than the boxes' padding), so a lane may test more surfaces, never fewer: the same
 * answer. */
#ifndef CLR_PACKET_SHADOWS16_CL
#define CLR_PACKET_SHADOWS16_CL

#include "common/hit_order.cl"
#include "common/bvh_nodes.cl"
#include "common/math.cl"
#include "common/scene_params.cl"
#include "intersect.cl"
#include "kinds/kinds.cl"
#include "packet/boxes16.cl"
#include "packet/lane_masks.cl"
#include "packet/packet_types.cl"
#include "packet/shading_modes.cl"
#include "shared/clr_types.h"

#if CLR_SUN_PACKETS

/* The shadow rays of one row: lane l starts at (ox, oy, oz)[l], goes along (dx, dy, dz)[l],
 * ends at t_max[l] and leaves surface (skip_kind, skip_index)[l]; only lanes with wanted[l]
 * are traced. Sets occluded[l] as occluded() would answer. */
typedef struct {
    real ox[16], oy[16], oz[16];
    real dx[16], dy[16], dz[16];
    real t_max[16];
    int skip_kind[16], skip_index[16];
    int wanted[16];
    int occluded[16];
} ShadowRays16;

/* Whether lane `lane` meets surface (kind, index) before its t_max (intersect_bvh()'s leaf
 * test with first_hit). */
bool lane_meets16(const ShadowRays16* rays, int lane, int kind, int index, CLR_SCENE_PARAMS)
{
    if (skips_surface(kind, index, rays->skip_kind[lane], rays->skip_index[lane]))
        return false;
    real3 origin = (real3)(rays->ox[lane], rays->oy[lane], rays->oz[lane]);
    real3 direction = (real3)(rays->dx[lane], rays->dy[lane], rays->dz[lane]);
    real t = kind_hit_distance(kind, index, origin, direction, INFINITY, CLR_SCENE_ARGS);
    Hit none;
    none.t = rays->t_max[lane];
    none.kind = CLR_HIT_NONE;
    none.index = -1;
    return hit_beats(t, kind, index, none);
}

/* The lanes among `reach` that surface (kind, index) may occlude: all but those whose rays
 * leave it (skips_surface() lane by lane). */
CLR_PACKET_INLINE mask16 lanes_tested16(int kind, int index, mask16 reach, int16 skip_kind, int16 skip_index)
{
#if CLR_FEATURE_TRIANGLE_TIES
    /* A pair (skips_surface()): the triangle skip_index and the one CLR_SKIP_PAIR - skip_kind. */
    int16 pair = skip_kind <= (int16)(CLR_SKIP_PAIR);
    int16 skipped = select(skip_kind == (int16)(kind) && skip_index == (int16)(index),
                           (int16)(kind == CLR_HIT_TRIANGLE ? -1 : 0) &
                               (skip_index == (int16)(index) || ((int16)(CLR_SKIP_PAIR) - skip_kind) == (int16)(index)),
                           pair);
    mask16 tested = reach & convert_mask16(!skipped);
#else
    mask16 tested = reach & convert_mask16(skip_kind != (int16)(kind) || skip_index != (int16)(index));
#endif
    return tested;
}

/* The lanes among `tested` whose rays surface (kind, index), at distances `t`, occludes: those
 * it meets before their t_max (hit_beats()). */
CLR_PACKET_INLINE int16 lanes_met16(real16 t, int kind, int index, mask16 tested, real16 t_max)
{
    return convert_int16(tested & hits_beat16(t, kind, index, t_max, (int16)(CLR_HIT_NONE), (int16)(-1)));
}

void occluded_lanes16(ShadowRays16* rays, CLR_SCENE_PARAMS)
{
    for (int lane = 0; lane < 16; ++lane)
        rays->occluded[lane] = 0;
    real16 ox = vload16(0, rays->ox), oy = vload16(0, rays->oy), oz = vload16(0, rays->oz);
    real16 dx = vload16(0, rays->dx), dy = vload16(0, rays->dy), dz = vload16(0, rays->dz);
    real16 t_max = vload16(0, rays->t_max);
    Points16 origins = {ox, oy, oz};
    Directions16 d = {dx, dy, dz};
    int16 skip_kind = vload16(0, rays->skip_kind), skip_index = vload16(0, rays->skip_index);
#if CLR_FEATURE_TRIANGLES
    /* triangle_plane_slack() lane by lane */
    real16 slack = (real)CLR_TRIANGLE_PLANE_SLACK * (fabs(ox) + fabs(oy) + fabs(oz));
#endif
    Directions16 inverse = safe_inverse16(d);
    mask16 open = convert_mask16(vload16(0, rays->wanted) != (int16)(0));
    uint stack[CLR_BVH_STACK];
    stack[0] = 0;
    int top = bvh_roots(info);
    while (top > 0 && any_lanes16(open)) {
        __global const ClrBvhNode* node = &bvh_nodes[stack[--top]];
        mask16 reach = open & box_reached16(node, origins, inverse, t_max);
        if (!any_lanes16(reach))
            continue;
        if (bvh_count(node) == 0) {
            stack[top++] = bvh_first(node) + 1;
            stack[top++] = bvh_first(node);
            continue;
        }
        int reaching[16];
        vstore16(convert_int16(reach), 0, reaching);
        int16 met = (int16)(0); /* lanes that a triangle of this leaf occludes */
        for (uint k = bvh_first(node), end = k + bvh_count(node); k < end; ++k) {
            int kind = item_kind(bvh_items[k]);
            int index = item_index(bvh_items[k]);
            /* All 16 lanes at once, as lane_meets16() would answer each. */
#if CLR_FEATURE_TRIANGLES
            if (kind == CLR_HIT_TRIANGLE) {
                /* Lanes already occluded, or leaving this triangle, need no answer from it. */
                mask16 tested = lanes_tested16(kind, index, reach & convert_mask16(met == (int16)(0)), skip_kind,
                                               skip_index);
                if (!any_lanes16(tested))
                    continue;
                real16 t = triangle_distance16_from(&triangles[index], origins, slack, d, tested);
                met |= lanes_met16(t, kind, index, tested, t_max);
                continue;
            }
#endif
#if CLR_FEATURE_SPHERES
            if (kind == CLR_HIT_SPHERE) {
                __global const ClrSphere* sphere = &spheres[index];
                real16 t = sphere_distance16_from(sphere->center_radius, sphere->color.w,
                                                  (sphere->flags & CLR_SURFACE_NEAR_EYE) != 0u, origins, d);
                met |= lanes_met16(t, kind, index, lanes_tested16(kind, index, reach, skip_kind, skip_index), t_max);
                continue;
            }
#endif
#if CLR_FEATURE_BILLBOARDS
            if (kind == CLR_HIT_BILLBOARD) {
                real16 t = billboard_distance16_from(&billboards[index], coverage, origins, d);
                met |= lanes_met16(t, kind, index, lanes_tested16(kind, index, reach, skip_kind, skip_index), t_max);
                continue;
            }
#endif
            for (int lane = 0; lane < 16; ++lane) {
                if (reaching[lane] && !rays->occluded[lane] && lane_meets16(rays, lane, kind, index, CLR_SCENE_ARGS))
                    rays->occluded[lane] = 1;
            }
        }
        int16 occluded = select(vload16(0, rays->occluded), (int16)(1), met);
        vstore16(occluded, 0, rays->occluded);
        open = open & convert_mask16(occluded == (int16)(0));
    }
    /* Planes lie in no BVH: a lane the BVH left unoccluded tests them, as occluded() does. */
    for (int lane = 0; lane < 16; ++lane) {
        if (!rays->wanted[lane] || rays->occluded[lane])
            continue;
        Hit hit;
        hit.t = rays->t_max[lane];
        hit.kind = CLR_HIT_NONE;
        hit.index = -1;
        nearest_plane((real3)(rays->ox[lane], rays->oy[lane], rays->oz[lane]),
                      (real3)(rays->dx[lane], rays->dy[lane], rays->dz[lane]), rays->skip_kind[lane],
                      rays->skip_index[lane], &hit, CLR_SCENE_ARGS);
        rays->occluded[lane] = hit.kind != CLR_HIT_NONE;
    }
}

#endif /* CLR_SUN_PACKETS */

#endif /* CLR_PACKET_SHADOWS16_CL */
