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
/* The lanes among `on` (lanes on triangles) whose hit point may lie on an edge or corner of the
 * triangle hit, 16 at once: triangle_settled_index()'s edge test with four times its band. A
 * point within the band of a corner c (|P - c|_1) is within the band of the edge from c
 * (|(P - c) x e|_1 <= |P - c|_1 |e|_1), and the margin covers the rounding, so every lane
 * that function settles is among these; it decides them one by one. Nearly every hit is far
 * from its triangle's edges: one lane at a time for all of them cost lit meshes a third of
 * their speed. */
CLR_PACKET_INLINE int16 near_edges16(real3 eye, Directions16 d, Hits16 hits, int16 on, CLR_SCENE_PARAMS)
{
    real cx[3][16], cy[3][16], cz[3][16];
    int indices[16];
    vstore16(select((int16)(-1), hits.index, on), 0, indices);
    for (int lane = 0; lane < 16; ++lane) {
        float4 c[3] = {(float4)(0.0f), (float4)(0.0f), (float4)(0.0f)};
        if (indices[lane] >= 0) {
            __global const ClrTriangle* triangle = &triangles[indices[lane]];
            c[0] = triangle->corner0;
            c[1] = triangle->corner1;
            c[2] = triangle->corner2;
        }
        for (int k = 0; k < 3; ++k) {
            cx[k][lane] = (real)c[k].x;
            cy[k][lane] = (real)c[k].y;
            cz[k][lane] = (real)c[k].z;
        }
    }
    real16 t = select(hits.t, (real16)(0.0f), convert_mask16(on == (int16)(0)));
    real16 px = eye.x + t * d.x, py = eye.y + t * d.y, pz = eye.z + t * d.z;
    real16 band = t * (real)(4.0f / 1048576.0f);
    mask16 near = convert_mask16((int16)(0));
    for (int k = 0; k < 3; ++k) {
        int a = (k + 1) % 3, b = (k + 2) % 3;
        real16 ax = vload16(0, cx[a]), ay = vload16(0, cy[a]), az = vload16(0, cz[a]);
        real16 ex = vload16(0, cx[b]) - ax, ey = vload16(0, cy[b]) - ay, ez = vload16(0, cz[b]) - az;
        real16 qx = px - ax, qy = py - ay, qz = pz - az;
        real16 xx = qy * ez - qz * ey, xy = qz * ex - qx * ez, xz = qx * ey - qy * ex;
        near = near | (fabs(xx) + fabs(xy) + fabs(xz) <= band * (fabs(ex) + fabs(ey) + fabs(ez)));
    }
    return convert_int16(near) & on;
}

/* `hits` with each lane on a triangle settled as shade_hit() settles it; `*others` receives each
 * lane's lowest other triangle there (its own index where none), which its shadow ray leaves too. */
CLR_PACKET_INLINE Hits16 settled_hits16(real3 eye, Directions16 d, Hits16 hits, int16* others, CLR_SCENE_PARAMS)
{
    *others = hits.index;
    int16 on = hits.kind == (int16)(CLR_HIT_TRIANGLE);
    if (!any_lanes16(on))
        return hits;
    int16 near = near_edges16(eye, d, hits, on, CLR_SCENE_ARGS);
    if (!any_lanes16(near))
        return hits;
    int near_lanes[16], indices[16], other[16];
    real ts[16], dx[16], dy[16], dz[16];
    vstore16(near, 0, near_lanes);
    vstore16(hits.index, 0, indices);
    vstore16(hits.t, 0, ts);
    vstore16(d.x, 0, dx);
    vstore16(d.y, 0, dy);
    vstore16(d.z, 0, dz);
    for (int lane = 0; lane < 16; ++lane) {
        other[lane] = indices[lane];
        if (!near_lanes[lane])
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
        float3 color = triangle_mesh_surface(indices[lane], CLR_SCENE_ARGS)->color.xyz;
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
