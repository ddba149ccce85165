/* The plane kind (ClrPlane): an infinite plane, seen from both sides. Where a ray meets it,
 * one ray and 16 at a time, its normal and its colour, as kinds/kinds.cl asks every kind.
 * A plane has no bounds, so no BVH and no screen tile holds it: intersect.cl and the packet
 * loop test every plane after the objects they cull (plane_count of them, a handful). A
 * secondary ray leaving a plane skips that plane, which it cannot meet again: no epsilon. */
#ifndef CLR_KINDS_PLANE_CL
#define CLR_KINDS_PLANE_CL

#include "common/math.cl"
#include "common/scene_params.cl"
#include "packet/lane_masks.cl"
#include "packet/packet_types.cl"
#include "shared/clr_types.h"

/* The origin's offset (P0 - o).n from the plane, the more exact of two ways: from the point as
 * stored, rounded to float relative to the eye (a plane through a point 1e12 away passed units
 * off the eye, and filled the image with the wrong side of it), or from the plane's offset
 * from the eye, which the host computed in double (ClrPlane point.w), less n.o; the second only
 * where the first's rounding bound is 4096 times its own, so that other planes keep their bits
 * (kinds/billboard.cl, billboard_offset()). */
real plane_offset(__global const ClrPlane* plane, real3 normal, real3 origin)
{
    real3 to_point = convert_real3(plane->point.xyz) - origin;
    real stored = (real)plane->point.w;
    real eye_error = fabs(stored) + abs_dot3(normal, origin);
    return eye_error * 4096.0f < abs_dot3(to_point, normal) ? stored - dot3(normal, origin) : dot3(to_point, normal);
}

/* The lecture's ray-plane intersection: t = ((P0 - o).n) / (d.n), kept when 0 < t < t_max;
 * a ray parallel to the plane (d.n = 0) misses it. */
real plane_hit_distance(int index, real3 origin, real3 direction, real t_max, CLR_SCENE_PARAMS)
{
    __global const ClrPlane* plane = &planes[index];
    real3 normal = convert_real3(plane->normal.xyz);
    real along = dot3(direction, normal);
    if (along == 0.0f)
        return INFINITY;
    real t = plane_offset(plane, normal, origin) / along;
    return t > 0.0f && t < t_max ? t : INFINITY;
}

/* plane_hit_distance() for 16 primary rays (t_max = infinity); a plane shows no texels. */
CLR_PACKET_INLINE real16 plane_hit_distance16(int index, real3 origin, Directions16 d, int want_texels, uint16* texel,
                                              CLR_SCENE_PARAMS)
{
    __global const ClrPlane* plane = &planes[index];
    real3 normal = convert_real3(plane->normal.xyz);
    real16 along = dot16(normal, d);
    real16 t = (real16)(plane_offset(plane, normal, origin)) / along;
    return select((real16)(INFINITY), t, along != 0.0f && t > 0.0f);
}

/* The plane's unit normal, turned to face the ray that arrives along `direction`. */
real3 plane_normal(int index, real3 point, real3 direction, CLR_SCENE_PARAMS)
{
    real3 normal = convert_real3(planes[index].normal.xyz);
    return dot3(normal, direction) > 0.0f ? -normal : normal;
}

uint plane_flags(int index, CLR_SCENE_PARAMS)
{
    return planes[index].flags;
}

uint plane_material(int index, CLR_SCENE_PARAMS)
{
    return planes[index].material;
}

/* The colour before lighting: its ambient colour. */
float3 plane_surface_color(int index, real3 origin, real3 direction, real t, CLR_SCENE_PARAMS)
{
    return planes[index].color.xyz;
}

CLR_PACKET_INLINE Colors16 plane_flat_colors16(int index, uint16 texel, CLR_SCENE_PARAMS)
{
    return uniform_colors16(planes[index].color.xyz);
}

/* Planes are lit as spheres are. */
bool plane_is_lit(void)
{
    return true;
}

CLR_PACKET_INLINE void plane_prefetch(int index, CLR_SCENE_PARAMS)
{
}

#endif /* CLR_KINDS_PLANE_CL */
