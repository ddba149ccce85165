/* Stage 3: shading a hit (docs/scene-format.md, Conventions: Lighting and shadows; Mirrors).
 * A hit either ends the path with a colour or, on the front of a mirror, continues it with a
 * reflected ray. */
#ifndef CLR_SHADE_CL
#define CLR_SHADE_CL

#include "common/math.cl"
#include "common/scene_params.cl"
#include "common/texture.cl"
#include "intersect.cl"
#include "shared/clr_types.h"

typedef struct {
    float3 color;     /* the path's colour, when it ends here */
    int bounces;      /* 1: continue along (next_origin, next_direction) instead */
    real3 next_origin;
    real3 next_direction;
    int leaving_kind; /* the mirror the reflected ray leaves */
    int leaving_index;
} ShadeResult;

/* The colour a sphere shows at distance t along the ray: its ambient colour, scaled in sun
 * mode by max(0, n.l) and by 0 when an opaque surface lies between the point and the sun.
 * Shading uses dot3() and unit3(), never the built-in dot(), length() or normalize(): their
 * order, FMAs and scaling are the implementation's, and Intel's CPU runtime and PoCL gave
 * pixels one display step apart; with + - * / and sqrt alone both give the same bytes. */
float3 sphere_color(int index, real3 origin, real3 direction, real t, CLR_SCENE_PARAMS)
{
    float3 ambient = spheres[index].color.xyz;
#if CLR_FEATURE_SUN
    if (!info.lit)
        return ambient;
    real3 point = origin + t * direction;
    real3 normal = unit3(point - convert_real3(spheres[index].center_radius.xyz));
    real3 to_sun = convert_real3(info.sun.xyz) - point;
    real sun_distance = sqrt(dot3(to_sun, to_sun));
    real3 light = to_sun / sun_distance;
    real cosine = dot3(normal, light);
    if (cosine <= 0.0f)
        return (float3)(0.0f); /* facing away: no shadow ray needed */
    Hit blocker = intersect_scene(point, light, sun_distance, CLR_HIT_SPHERE, index, CLR_SCENE_ARGS);
    return blocker.kind == CLR_HIT_NONE ? ambient * (float)cosine : (float3)(0.0f);
#else
    return ambient;
#endif
}

/* The colour a billboard shows at distance t: its texel (opaque, or the ray would have
 * passed through) or its flat colour. Billboards are pictures and stay unlit. */
float3 billboard_color(int index, real3 origin, real3 direction, real t, CLR_SCENE_PARAMS)
{
    __global const ClrBillboard* billboard = &billboards[index];
#if CLR_FEATURE_TEXTURES
    if (billboard->flags & CLR_SURFACE_TEXTURED) {
        real2 ab = billboard_coords(billboard, origin, direction, t);
        return texel_color(billboard_texel(billboard, texels, ab.x, ab.y));
    }
#endif
    return billboard->color.xyz;
}

/* Shades `hit` of the ray (origin, direction) after `reflections` mirror bounces. */
ShadeResult shade_hit(Hit hit, real3 origin, real3 direction, int reflections, CLR_SCENE_PARAMS)
{
    ShadeResult result;
    result.bounces = 0;
    result.color = info.background.xyz;
    if (hit.kind == CLR_HIT_NONE)
        return result;
#if CLR_FEATURE_MIRRORS
    uint flags = hit.kind == CLR_HIT_SPHERE ? spheres[hit.index].flags : billboards[hit.index].flags;
    if (flags & CLR_SURFACE_MIRROR) {
        real3 point = origin + hit.t * direction;
        real3 normal = hit.kind == CLR_HIT_SPHERE ? unit3(point - convert_real3(spheres[hit.index].center_radius.xyz))
                                                  : convert_real3(billboards[hit.index].normal.xyz);
        if (dot3(direction, normal) >= 0.0f) {
            result.color = (float3)(0.0f); /* the back of a mirror is black */
            return result;
        }
        if (reflections >= info.max_depth)
            return result; /* one reflection too many: background */
        result.bounces = 1;
        result.next_origin = point;
        result.next_direction = unit3(reflect_direction(direction, normal));
        result.leaving_kind = hit.kind;
        result.leaving_index = hit.index;
        return result;
    }
#endif
    if (hit.kind == CLR_HIT_SPHERE)
        result.color = sphere_color(hit.index, origin, direction, hit.t, CLR_SCENE_ARGS);
    else
        result.color = billboard_color(hit.index, origin, direction, hit.t, CLR_SCENE_ARGS);
    return result;
}

#endif /* CLR_SHADE_CL */
