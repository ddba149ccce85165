/* The sun-alone shading mode (CLR_SUN_PACKETS, shading_modes.cl): a packet's lanes on lit
 * kinds shaded as surface_color() (shade.cl) shades them, lanes on triangles 16 at once, and
 * their shadow rays traced together (packet/shadows16.cl). */
#ifndef CLR_PACKET_SUNLIT16_CL
#define CLR_PACKET_SUNLIT16_CL

#include "common/math.cl"
#include "common/scene_params.cl"
#include "kinds/kinds.cl"
#include "packet/lane_masks.cl"
#include "packet/lanes16.cl"
#include "packet/packet_types.cl"
#include "packet/settled16.cl"
#include "packet/shading_modes.cl"
#include "packet/shadows16.cl"
#include "shared/clr_types.h"

#if CLR_SUN_PACKETS

/* Lane `lane`'s shadow ray: from `point` towards the sun along `light`, as far as the sun,
 * leaving surface (kind, index). */
CLR_PACKET_INLINE void want_shadow_ray16(ShadowRays16* rays, int lane, real3 point, real3 light, real sun_distance,
                                         int kind, int index)
{
    rays->wanted[lane] = 1;
    rays->ox[lane] = point.x;
    rays->oy[lane] = point.y;
    rays->oz[lane] = point.z;
    rays->dx[lane] = light.x;
    rays->dy[lane] = light.y;
    rays->dz[lane] = light.z;
    rays->t_max[lane] = sun_distance;
    rays->skip_kind[lane] = kind;
    rays->skip_index[lane] = index;
}

/* What a packet's lanes on lit kinds need from the sun, vector by vector: each lane's colour
 * so far (its flat colour, or black where it faces away from the sun), its lit colour, and
 * its shadow ray (ShadowRays16, whose wanted[] says which lanes have one). */
typedef struct {
    Colors16 color, lit;
    ShadowRays16 rays;
} SunlitLanes16;

#if CLR_FEATURE_TRIANGLES
/* The lanes of `hits` on triangles in a lit scene, shaded as sunlit_colors16() shades a lane
 * (each lane's values the same bits), 16 at once: a lane facing away from the sun turns black,
 * a lane facing it gets its lit colour and its shadow ray. */
CLR_PACKET_INLINE void sunlit_triangles16(real3 eye, Directions16 d, Hits16 hits, int16 leaving, int16 others,
                                          SunlitLanes16* out,
                                          CLR_SCENE_PARAMS)
{
    int16 on = hits.kind == (int16)(CLR_HIT_TRIANGLE);
    if (!any_lanes16(on))
        return;
    int indices[16];
    vstore16(select((int16)(-1), hits.index, on), 0, indices);
    Points16 point; /* eye + t * direction */
    point.x = eye.x + hits.t * d.x;
    point.y = eye.y + hits.t * d.y;
    point.z = eye.z + hits.t * d.z;
    Directions16 normal = triangle_normals16(indices, point, d, CLR_SCENE_ARGS);
    real3 sun = convert_real3(info.sun.xyz);
    real16 sx = sun.x - point.x, sy = sun.y - point.y, sz = sun.z - point.z;
    real16 sun_distance = sqrt(sx * sx + sy * sy + sz * sz);
    Directions16 light;
    light.x = sx / sun_distance;
    light.y = sy / sun_distance;
    light.z = sz / sun_distance;
    real16 cosine = normal.x * light.x + normal.y * light.y + normal.z * light.z;
    int16 away = on & convert_int16(cosine <= 0.0f); /* no shadow ray needed */
    int16 lit = on & ~away;
    out->color.r = select(out->color.r, (float16)(0.0f), away);
    out->color.g = select(out->color.g, (float16)(0.0f), away);
    out->color.b = select(out->color.b, (float16)(0.0f), away);
    float4 colors[16]; /* triangle_surface_color() */
    for (int lane = 0; lane < 16; ++lane)
        colors[lane] = indices[lane] < 0 ? (float4)(0.0f) : triangle_mesh_surface(indices[lane], CLR_SCENE_ARGS)->color;
    float16 r, g, b;
    float_columns16(colors, &r, &g, &b);
    float16 shade = convert_float16(cosine);
    out->lit.r = select(out->lit.r, r * shade, lit);
    out->lit.g = select(out->lit.g, g * shade, lit);
    out->lit.b = select(out->lit.b, b * shade, lit);
    ShadowRays16* rays = &out->rays;
    mask16 ray = convert_mask16(lit);
    vstore16(select(vload16(0, rays->wanted), (int16)(1), lit), 0, rays->wanted);
    vstore16(select(vload16(0, rays->ox), point.x, ray), 0, rays->ox);
    vstore16(select(vload16(0, rays->oy), point.y, ray), 0, rays->oy);
    vstore16(select(vload16(0, rays->oz), point.z, ray), 0, rays->oz);
    vstore16(select(vload16(0, rays->dx), light.x, ray), 0, rays->dx);
    vstore16(select(vload16(0, rays->dy), light.y, ray), 0, rays->dy);
    vstore16(select(vload16(0, rays->dz), light.z, ray), 0, rays->dz);
    vstore16(select(vload16(0, rays->t_max), sun_distance, ray), 0, rays->t_max);
    /* The triangle hit and, where it was settled, the lowest other one there (skip_kind_of_pair()). */
    int16 pair_kind = select((int16)(CLR_SKIP_PAIR) - others, (int16)(CLR_HIT_TRIANGLE), others == leaving);
    vstore16(select(vload16(0, rays->skip_kind), pair_kind, lit), 0, rays->skip_kind);
    vstore16(select(vload16(0, rays->skip_index), leaving, lit), 0, rays->skip_index);
}
#endif

/* The lanes in `by_lane`, one by one: surface_color() in sun mode, up to each lane's shadow
 * ray, into `out` (whose colours are the lanes' flat ones). */
CLR_PACKET_INLINE void sunlit_lanes_one_by_one16(real3 eye, Directions16 d, Hits16 hits, int16 by_lane,
                                                 SunlitLanes16* out, CLR_SCENE_PARAMS)
{
    Lanes16 lanes;
    unpack_lanes16(d, hits, &out->color, &lanes);
    float lit_r[16], lit_g[16], lit_b[16];
    vstore16((float16)(0.0f), 0, lit_r);
    vstore16((float16)(0.0f), 0, lit_g);
    vstore16((float16)(0.0f), 0, lit_b);
    int one_by_one[16];
    vstore16(by_lane, 0, one_by_one);
    for (int lane = 0; lane < 16; ++lane) {
        if (!one_by_one[lane])
            continue;
        const int kind = lanes.kind[lane], index = lanes.index[lane];
        real3 direction = (real3)(lanes.x[lane], lanes.y[lane], lanes.z[lane]);
        float3 color = kind_surface_color(kind, index, eye, direction, lanes.t[lane], CLR_SCENE_ARGS);
        if (!info.lit) {
            set_lane_color16(&lanes, lane, color);
            continue;
        }
        real3 point = eye + lanes.t[lane] * direction;
        real3 normal = kind_normal(kind, index, point, direction, CLR_SCENE_ARGS);
        real3 to_sun = convert_real3(info.sun.xyz) - point;
        real sun_distance = sqrt(dot3(to_sun, to_sun));
        real3 light = to_sun / sun_distance;
        real cosine = dot3(normal, light);
        if (cosine <= 0.0f) {
            set_lane_color16(&lanes, lane, (float3)(0.0f)); /* facing away: no shadow ray needed */
            continue;
        }
        float3 lit = color * (float)cosine;
        lit_r[lane] = lit.x;
        lit_g[lane] = lit.y;
        lit_b[lane] = lit.z;
        want_shadow_ray16(&out->rays, lane, point, light, sun_distance, kind, index);
    }
    out->color = lane_colors16(&lanes);
    out->lit.r = vload16(0, lit_r);
    out->lit.g = vload16(0, lit_g);
    out->lit.b = vload16(0, lit_b);
}

/* traced_colors16() with `flat` in the sun-alone mode: each lane on a lit kind shaded as
 * surface_color() shades it, with the 16 lanes' shadow rays traced together
 * (occluded_lanes16()): the same colours. Lanes without a shadow ray still take part in its
 * vectors, with any finite values. */
CLR_PACKET_INLINE Colors16 sunlit_colors16(real3 eye, Directions16 d, Hits16 hits, Colors16 flat, CLR_SCENE_PARAMS)
{
    SunlitLanes16 out;
    ShadowRays16* rays = &out.rays;
    vstore16((int16)(0), 0, rays->wanted);
    vstore16((real16)(0.0f), 0, rays->ox);
    vstore16((real16)(0.0f), 0, rays->oy);
    vstore16((real16)(0.0f), 0, rays->oz);
    vstore16((real16)(1.0f), 0, rays->dx);
    vstore16((real16)(1.0f), 0, rays->dy);
    vstore16((real16)(1.0f), 0, rays->dz);
    vstore16((real16)(0.0f), 0, rays->t_max);
    vstore16((int16)(CLR_HIT_NONE), 0, rays->skip_kind);
    vstore16((int16)(-1), 0, rays->skip_index);
#if CLR_FEATURE_TRIANGLES
    int16 leaving = hits.index; /* the triangles hit, which their shadow rays skip (shade_hit()) */
    int16 others = hits.index;  /* and the lowest other triangle where a hit was settled */
#if CLR_FEATURE_TRIANGLE_TIES
    hits = settled_hits16(eye, d, hits, &others, CLR_SCENE_ARGS);
#endif
#endif
    /* Lanes on other lit kinds (and every lit lane of a scene the sun does not light), one by
     * one: surface_color() in sun mode, up to its shadow ray. */
    int16 by_lane = lit_lanes16(hits.kind);
#if CLR_FEATURE_TRIANGLES
    if (info.lit)
        by_lane = by_lane & (hits.kind != (int16)(CLR_HIT_TRIANGLE));
#endif
    out.color = flat;
    out.lit.r = out.lit.g = out.lit.b = (float16)(0.0f);
    if (any_lanes16(by_lane))
        sunlit_lanes_one_by_one16(eye, d, hits, by_lane, &out, CLR_SCENE_ARGS);
#if CLR_FEATURE_TRIANGLES
    if (info.lit)
        sunlit_triangles16(eye, d, hits, leaving, others, &out, CLR_SCENE_ARGS);
#endif
    int16 wanted = vload16(0, rays->wanted) != (int16)(0);
    if (!any_lanes16(wanted))
        return out.color;
    occluded_lanes16(rays, CLR_SCENE_ARGS);
    int16 sunlit = wanted & (vload16(0, rays->occluded) == (int16)(0));
    int16 shadowed = wanted & ~sunlit;
    Colors16 color = out.color;
    color.r = select(select(color.r, (float16)(0.0f), shadowed), out.lit.r, sunlit);
    color.g = select(select(color.g, (float16)(0.0f), shadowed), out.lit.g, sunlit);
    color.b = select(select(color.b, (float16)(0.0f), shadowed), out.lit.b, sunlit);
    return color;
}

#endif /* CLR_SUN_PACKETS */

#endif /* CLR_PACKET_SUNLIT16_CL */
