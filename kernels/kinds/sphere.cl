/* The sphere kind (ClrSphere): where a ray meets it, one ray and 16 at a time, its normal and
 * its colour. Every kind gives kinds/kinds.cl the same functions, with the same parameters. */
#ifndef CLR_KINDS_SPHERE_CL
#define CLR_KINDS_SPHERE_CL

#include "common/math.cl"
#include "common/scene_params.cl"
#include "packet/lane_masks.cl"
#include "packet/packet_types.cl"
#include "shared/clr_types.h"

/* A sphere's power c = |o - centre|^2 - r^2 at the ray's origin o (negative inside), the more
 * exact of two ways. From oc = o - centre as stored, |oc|^2 - r^2: both squares round by a
 * share of their size, so near the surface of a sphere far larger than that distance (a ground
 * sphere of radius 1e8 under an eye 1.4 above it: squares of 1e16, c of 2.8e8) c was noise,
 * its sign, whether the origin is inside, too, and the image went black. From the power of the
 * eye that the host computed in double (`c_eye`, ClrSphere color.w) and the origin relative to
 * it: c_eye + o.(o - 2 centre), exact near the eye (o = 0 for a primary ray). The second is
 * taken only where the first's rounding bound is 4096 times its own, so that every sphere not
 * so near the origin keeps its bits. That needs 4096 |c_eye| < |centre - eye|^2 + r^2 whatever
 * the origin; the host marks the spheres that meet it with a margin (CLR_SURFACE_NEAR_EYE),
 * and the others take the first without the test (`near_eye` false). */
real sphere_power(real c_eye, real3 oc, real3 center, real3 origin, real radius)
{
    real from_oc = dot3(oc, oc) - radius * radius;
    real oc_error = dot3(oc, oc) + radius * radius;
    real3 away = oc - center;
    real from_eye = c_eye + dot3(origin, away);
    real eye_error = fabs(c_eye) + abs_dot3(origin, away);
    return eye_error * 4096.0f < oc_error ? from_eye : from_oc;
}

/* Distance along the unit direction to the nearest intersection with t > 0, or +inf.
 * Float32-robust form (Ray Tracing Gems, ch. 7): the discriminant is computed from the
 * distance between the centre and the ray's closest point instead of b*b - c, which would
 * cancel catastrophically for small or distant spheres, and the two roots come from
 * q = b + sign(b) sqrt(discriminant) as c/q and q, so neither subtracts nearly equal values. */
real sphere_distance(float4 center_radius, real c_eye, bool near_eye, real3 origin, real3 direction)
{
    real radius = center_radius.w;
    real3 center = convert_real3(center_radius.xyz);
    real3 oc = origin - center;
    real b = -dot3(oc, direction);              /* t of the closest approach */
    real3 closest_offset = oc + b * direction; /* centre -> closest point on the ray */
    real discriminant = radius * radius - dot3(closest_offset, closest_offset);
    if (discriminant < 0.0f)
        return INFINITY;
    real c = near_eye ? sphere_power(c_eye, oc, center, origin, radius) : dot3(oc, oc) - radius * radius;
    real q = b + copysign(sqrt(discriminant), b);
    if (q == 0.0f) /* tangent exactly at the origin */
        return INFINITY;
    real t0 = c / q;
    real t1 = q;
    real t_near = fmin(t0, t1);
    real t_far = fmax(t0, t1);
    if (t_near > 0.0f)
        return t_near;
    return t_far > 0.0f ? t_far : INFINITY; /* origin inside the sphere: the far side */
}

/* The nearer root t > 0 of 16 rays' quadratics as sphere_distance() finds it, from b (the t of
 * each ray's closest approach), the discriminant and c (|origin - centre|^2 - radius^2): +inf
 * where there is none. */
CLR_PACKET_INLINE real16 sphere_root16(real16 b, real16 discriminant, real16 c)
{
    real16 q = b + copysign(sqrt(discriminant), b);
    real16 t0 = c / q;
    real16 t1 = q;
    real16 t_near = fmin(t0, t1);
    real16 t_far = fmax(t0, t1);
    real16 t = select(select((real16)(INFINITY), t_far, t_far > 0.0f), t_near, t_near > 0.0f);
    return select(t, (real16)(INFINITY), discriminant < 0.0f || q == 0.0f);
}

/* sphere_distance() for 16 rays from one origin. */
CLR_PACKET_INLINE real16 sphere_distance16(float4 center_radius, real c_eye, bool near_eye, real3 origin,
                                           Directions16 d)
{
    real radius = center_radius.w;
    real3 center = convert_real3(center_radius.xyz);
    real3 oc = origin - center;
    real16 b = -dot16(oc, d);
    real16 cx = oc.x + b * d.x, cy = oc.y + b * d.y, cz = oc.z + b * d.z;
    real16 discriminant = radius * radius - (cx * cx + cy * cy + cz * cz);
    if (!any_lanes16(discriminant >= 0.0f))
        return (real16)(INFINITY); /* all 16 rays miss: skip the square root and division */
    real c = near_eye ? sphere_power(c_eye, oc, center, origin, radius) : dot3(oc, oc) - radius * radius;
    return sphere_root16(b, discriminant, (real16)(c));
}

/* sphere_distance() for 16 rays from 16 origins, the shadow rays of a packet's hit points
 * (packet/shadows16.cl): lane by lane the same operations in the same order, so each lane's t is
 * the one sphere_distance() gives its ray, to the last bit. */
CLR_PACKET_INLINE real16 sphere_distance16_from(float4 center_radius, real c_eye, bool near_eye, Points16 o,
                                                Directions16 d)
{
    real radius = center_radius.w;
    real16 ocx = o.x - (real)center_radius.x, ocy = o.y - (real)center_radius.y, ocz = o.z - (real)center_radius.z;
    real16 b = -(ocx * d.x + ocy * d.y + ocz * d.z); /* -dot3(oc, direction) */
    real16 cx = ocx + b * d.x, cy = ocy + b * d.y, cz = ocz + b * d.z;
    real16 discriminant = radius * radius - (cx * cx + cy * cy + cz * cz);
    if (!any_lanes16(discriminant >= 0.0f))
        return (real16)(INFINITY); /* all 16 rays miss: skip the square root and division */
    real16 squared = ocx * ocx + ocy * ocy + ocz * ocz;
    real16 c = squared - radius * radius;
    if (near_eye) { /* sphere_power() lane by lane */
        real16 ax = ocx - (real)center_radius.x, ay = ocy - (real)center_radius.y, az = ocz - (real)center_radius.z;
        real16 from_eye = c_eye + (o.x * ax + o.y * ay + o.z * az);
        real16 eye_error = fabs(c_eye) + (fabs(o.x * ax) + fabs(o.y * ay) + fabs(o.z * az));
        c = select(c, from_eye, eye_error * 4096.0f < squared + radius * radius);
    }
    return sphere_root16(b, discriminant, c);
}

/* The kind's functions for kinds/kinds.cl. */

/* Sphere `index` as a ray from `origin` meets it, with 0 < t < t_max or +inf (a sphere's hit
 * needs no t_max: the caller compares). */
real sphere_hit_distance(int index, real3 origin, real3 direction, real t_max, CLR_SCENE_PARAMS)
{
    __global const ClrSphere* sphere = &spheres[index];
    return sphere_distance(sphere->center_radius, sphere->color.w, (sphere->flags & CLR_SURFACE_NEAR_EYE) != 0u, origin,
                           direction);
}

/* sphere_hit_distance() for 16 primary rays; a sphere shows no texels. */
CLR_PACKET_INLINE real16 sphere_hit_distance16(int index, real3 origin, Directions16 d, int want_texels,
                                               uint16* texel, CLR_SCENE_PARAMS)
{
    __global const ClrSphere* sphere = &spheres[index];
    return sphere_distance16(sphere->center_radius, sphere->color.w, (sphere->flags & CLR_SURFACE_NEAR_EYE) != 0u,
                             origin, d);
}

/* The unit outward normal at `point` on the sphere. */
real3 sphere_normal(int index, real3 point, real3 direction, CLR_SCENE_PARAMS)
{
    return unit3(point - convert_real3(spheres[index].center_radius.xyz));
}

uint sphere_flags(int index, CLR_SCENE_PARAMS)
{
    return spheres[index].flags;
}

/* Its Blinn-Phong material (ClrMaterial) in `materials`. */
uint sphere_material(int index, CLR_SCENE_PARAMS)
{
    return spheres[index].material;
}

/* The colour before lighting: the ambient colour. */
float3 sphere_surface_color(int index, real3 origin, real3 direction, real t, CLR_SCENE_PARAMS)
{
    return spheres[index].color.xyz;
}

/* sphere_surface_color() of 16 lanes that hit the sphere. */
CLR_PACKET_INLINE Colors16 sphere_flat_colors16(int index, uint16 texel, CLR_SCENE_PARAMS)
{
    return uniform_colors16(spheres[index].color.xyz);
}

/* Spheres are lit by the sun (docs/scene-format.md, Conventions: Lighting and shadows): in a
 * lit scene shade.cl scales their colour by max(0, n.l) and the sun's visibility. */
bool sphere_is_lit(void)
{
    return true;
}

/* Nothing to fetch ahead of a sphere's test. */
CLR_PACKET_INLINE void sphere_prefetch(int index, CLR_SCENE_PARAMS)
{
}

#endif /* CLR_KINDS_SPHERE_CL */
