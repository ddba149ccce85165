/* A packet's 16 primary rays through the BVH together, instead of through its screen tile's
 * list (ClrSceneInfo::primary_bvh, chosen by the host where meshes are large:
 * host/render/primary_ray_path.h). Binning a million triangles into tiles every frame cost
 * about as much host time as the kernel's primary rays; the BVH is built once, and a packet
 * finds the few triangles near its rays in a walk of a few dozen boxes (docs/benchmarks.md,
 * Primary packets through the BVH).
 *
 * Each lane's answer is the tile loop's: every object a lane reaches is tested by the same
 * keep_nearer16() and ranked by hits_beat16(), in whatever order. A box is entered where some
 * lane's ray reaches it no farther than that lane's best hit so far (box_reachable() lane by
 * lane, with intersect_bvh()'s rule for the nearest hit), so no lane misses an object that
 * could beat its hit; the nearer child first, so that far boxes are mostly passed by. The walk
 * starts at the entries its screen tile found (packet/bvh_entries.cl), below the levels that
 * every packet of the tile would test alike. */
#ifndef CLR_PACKET_BVH_WALK16_CL
#define CLR_PACKET_BVH_WALK16_CL

#include "common/bvh_nodes.cl"
#include "common/math.cl"
#include "common/scene_items.cl"
#include "common/scene_params.cl"
#include "intersect.cl"
#include "packet/bvh_entries.cl"
#include "packet/boxes16.cl"
#include "packet/keep_nearer16.cl"
#include "packet/lane_masks.cl"
#include "packet/packet_types.cl"
#include "shared/clr_types.h"

#if CLR_FEATURE_BVH

/* keep_nearer16() for every object of the BVH that some lane of the 16 rays from `origin`
 * along `d` may meet before its hit in `best`: those under `entries` (bvh_entries()). */
CLR_PACKET_INLINE void nearest_in_bvh16(real3 origin, Directions16 d, const BvhEntries* entries, Hits16* best,
                                        Colors16* colors, uint16* best_texel, CLR_SCENE_PARAMS)
{
    Directions16 inverse = safe_inverse16(d);
    Points16 eye = {(real16)(origin.x), (real16)(origin.y), (real16)(origin.z)};
    real3 lead = (real3)(d.x.s7, d.y.s7, d.z.s7); /* a middle lane's direction */
    uint stack[CLR_BVH_STACK + CLR_BVH_ENTRIES]; /* the entries, and below one of them its walk's */
    int top = 0;
    for (int i = entries->count - 1; i >= 0; --i) /* the nearest popped first */
        stack[top++] = entries->node[i];
    while (top > 0) {
        __global const ClrBvhNode* node = &bvh_nodes[stack[--top]];
        if (!any_lanes16(box_reached16(node, eye, inverse, best->t)))
            continue;
        if (bvh_count(node) == 0) {
            __global const ClrBvhNode* left = &bvh_nodes[bvh_first(node)];
            bool left_first = centre_along(left, origin, lead) <= centre_along(left + 1, origin, lead);
            stack[top++] = left_first ? bvh_first(node) + 1 : bvh_first(node); /* popped second */
            stack[top++] = left_first ? bvh_first(node) : bvh_first(node) + 1;
            continue;
        }
        for (uint k = bvh_first(node), end = k + bvh_count(node); k < end; ++k)
            keep_nearer16(item_kind(bvh_items[k]), item_index(bvh_items[k]), origin, d, best, colors, best_texel,
                          CLR_SCENE_ARGS);
    }
}

#endif /* CLR_FEATURE_BVH */

#endif /* CLR_PACKET_BVH_WALK16_CL */
