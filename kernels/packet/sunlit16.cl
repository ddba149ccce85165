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

#if CLR_FEATURE_TRIANGLES
/* The lanes of `hits` on triangles in a lit scene, shaded as sunlit_colors16() shades a lane,
 * the 16 at once (each lane's values the same bits): a lane facing away from the sun turns
 * black, a lane facing it gets its lit colour in lit[lane] and its shadow ray in `rays`.
 * Returns how many shadow rays it wants. */
CLR_PACKET_INLINE int sunlit_triangles16(real3 eye, Directions16 d, Hits16 hits, Lanes16* lanes, float3* lit,
                                         ShadowRays16* rays, CLR_SCENE_PARAMS)
{
    int16 on = hits.kind == (int16)(CLR_HIT_TRIANGLE);
    if (!any_lanes16(on))
        return 0;
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
    real c[16], px[16], py[16], pz[16], lx[16], ly[16], lz[16], distance[16];
    vstore16(cosine, 0, c);
    vstore16(point.x, 0, px);
    vstore16(point.y, 0, py);
    vstore16(point.z, 0, pz);
    vstore16(light.x, 0, lx);
    vstore16(light.y, 0, ly);
    vstore16(light.z, 0, lz);
    vstore16(sun_distance, 0, distance);
    int shadow_rays = 0;
    for (int lane = 0; lane < 16; ++lane) {
        const int index = indices[lane];
        if (index < 0)
            continue;
        if (c[lane] <= 0.0f) {
            set_lane_color16(lanes, lane, (float3)(0.0f)); /* facing away: no shadow ray needed */
            continue;
        }
        lit[lane] = triangles[index].color.xyz * (float)c[lane]; /* triangle_surface_color() */
        want_shadow_ray16(rays, lane, (real3)(px[lane], py[lane], pz[lane]), (real3)(lx[lane], ly[lane], lz[lane]),
                          distance[lane], CLR_HIT_TRIANGLE, index);
        ++shadow_rays;
    }
    return shadow_rays;
}
#endif

/* traced_colors16() with `flat` in the sun-alone mode: each lane on a lit kind shaded as
 * surface_color() shades it, with the 16 lanes' shadow rays traced together
 * (occluded_lanes16()): the same colours. */
CLR_PACKET_INLINE Colors16 sunlit_colors16(real3 eye, Directions16 d, Hits16 hits, Colors16 flat, CLR_SCENE_PARAMS)
{
    Lanes16 lanes;
    unpack_lanes16(d, hits, &flat, &lanes);
    float3 lit[16];
    ShadowRays16 rays;
    for (int lane = 0; lane < 16; ++lane)
        rays.wanted[lane] = 0;
    int shadow_rays = 0;
#if CLR_FEATURE_TRIANGLES
    if (info.lit)
        shadow_rays += sunlit_triangles16(eye, d, hits, &lanes, lit, &rays, CLR_SCENE_ARGS);
#endif
    for (int lane = 0; lane < 16; ++lane) {
        const int kind = lanes.kind[lane], index = lanes.index[lane];
        if (!kind_is_lit(kind))
            continue; /* its flat colour is in lanes.r, g, b already */
        if (CLR_FEATURE_TRIANGLES && info.lit && kind == CLR_HIT_TRIANGLE)
            continue; /* shaded by sunlit_triangles16() */
        real3 direction = (real3)(lanes.x[lane], lanes.y[lane], lanes.z[lane]);
        /* surface_color() in sun mode, up to its shadow ray. */
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
        lit[lane] = color * (float)cosine;
        want_shadow_ray16(&rays, lane, point, light, sun_distance, kind, index);
        ++shadow_rays;
    }
    if (shadow_rays > 0) {
        /* Lanes without a shadow ray still take part in the vectors: any finite values. */
        for (int lane = 0; lane < 16; ++lane) {
            if (rays.wanted[lane])
                continue;
            rays.ox[lane] = rays.oy[lane] = rays.oz[lane] = 0.0f;
            rays.dx[lane] = rays.dy[lane] = rays.dz[lane] = 1.0f;
            rays.t_max[lane] = 0.0f;
        }
        occluded_lanes16(&rays, CLR_SCENE_ARGS);
        for (int lane = 0; lane < 16; ++lane) {
            if (rays.wanted[lane])
                set_lane_color16(&lanes, lane, rays.occluded[lane] ? (float3)(0.0f) : lit[lane]);
        }
    }
    return lane_colors16(&lanes);
}

#endif /* CLR_SUN_PACKETS */

#endif /* CLR_PACKET_SUNLIT16_CL */
