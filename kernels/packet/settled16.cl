/* A packet's hits on shared mesh edges and corners settled on the triangle they are shaded as
 * (kinds/triangle.cl, triangle_settled_index(); docs/scene-format.md, Meshes, "Shared edges and
 * vertices"), for the packet shading modes that do not go through shade_hit(). */
#ifndef CLR_PACKET_SETTLED16_CL
#define CLR_PACKET_SETTLED16_CL

#include "common/math.cl"
#include "common/scene_params.cl"
#include "kinds/kinds.cl"
#include "packet/lane_masks.cl"
#include "packet/packet_types.cl"
#include "shared/clr_types.h"

#if CLR_FEATURE_TRIANGLE_TIES && CLR_FEATURE_TRIANGLES
/* `hits` with each lane on a triangle settled as shade_hit() settles it; `*others` receives each
 * lane's lowest other triangle there (its own index where none), which its shadow ray leaves too. */
CLR_PACKET_INLINE Hits16 settled_hits16(real3 eye, Directions16 d, Hits16 hits, int16* others, CLR_SCENE_PARAMS)
{
    *others = hits.index;
    if (!any_lanes16(hits.kind == (int16)(CLR_HIT_TRIANGLE)))
        return hits;
    int kinds[16], indices[16], other[16];
    real ts[16], dx[16], dy[16], dz[16];
    vstore16(hits.kind, 0, kinds);
    vstore16(hits.index, 0, indices);
    vstore16(hits.t, 0, ts);
    vstore16(d.x, 0, dx);
    vstore16(d.y, 0, dy);
    vstore16(d.z, 0, dz);
    for (int lane = 0; lane < 16; ++lane) {
        other[lane] = indices[lane];
        if (kinds[lane] != CLR_HIT_TRIANGLE)
            continue;
        real3 point = eye + ts[lane] * (real3)(dx[lane], dy[lane], dz[lane]);
        indices[lane] = triangle_settled_index(indices[lane], point, ts[lane], &other[lane], CLR_SCENE_ARGS);
    }
    hits.index = vload16(0, indices);
    *others = vload16(0, other);
    return hits;
}
#endif

#if CLR_FEATURE_TRIANGLE_TIES && CLR_FEATURE_TRIANGLES
/* `flat` with each lane on a triangle given the colour of the triangle it settles on: flat
 * shading needs this only where triangles of different colours share corners (the `triangle`
 * surfaces of a scene: FeatureSet::triangle_ties). */
CLR_PACKET_INLINE Colors16 settled_flat_colors16(real3 eye, Directions16 d, Hits16 hits, Colors16 flat, CLR_SCENE_PARAMS)
{
    int16 others;
    Hits16 settled = settled_hits16(eye, d, hits, &others, CLR_SCENE_ARGS);
    int16 moved = settled.index != hits.index;
    if (!any_lanes16(moved))
        return flat;
    int indices[16], moved_lanes[16];
    float r[16], g[16], b[16];
    vstore16(settled.index, 0, indices);
    vstore16(moved, 0, moved_lanes);
    vstore16(flat.r, 0, r);
    vstore16(flat.g, 0, g);
    vstore16(flat.b, 0, b);
    for (int lane = 0; lane < 16; ++lane) {
        if (!moved_lanes[lane])
            continue;
        float3 color = triangles[indices[lane]].color.xyz;
        r[lane] = color.x;
        g[lane] = color.y;
        b[lane] = color.z;
    }
    flat.r = vload16(0, r);
    flat.g = vload16(0, g);
    flat.b = vload16(0, b);
    return flat;
}
#endif

#endif /* CLR_PACKET_SETTLED16_CL */
