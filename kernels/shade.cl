/* Stage 3: shading a hit (docs/scene-format.md, Conventions: Lighting and shadows; Mirrors).
 * A hit either ends the path with a colour or, on the front of a mirror, continues it with a
 * reflected ray. */
#ifndef CLR_SHADE_CL
#define CLR_SHADE_CL

#include "common/math.cl"
#include "common/scene_params.cl"
#include "intersect.cl"
#include "kinds/kinds.cl"
#include "shared/clr_types.h"

typedef struct {
    float3 color;     /* the path's colour, when it ends here; with lights, the share the surface adds */
    int bounces;      /* 1: continue along (next_origin, next_direction) instead */
#if CLR_FEATURE_LIGHTS
    float3 weight;    /* with `bounces`: the share of the reflected ray's colour added (k_m) */
#endif
    real3 next_origin;
    real3 next_direction;
    int leaving_kind; /* the mirror the reflected ray leaves */
    int leaving_index;
} ShadeResult;

#if CLR_FEATURE_LIGHTS
/* The Blinn-Phong model with point lights (docs/scene-format.md, Lights and materials): the
 * ambient colour, plus for each light on the side of the surface the ray sees (n.l > 0) and
 * hidden by no opaque surface, its colour times k_d n.l + k_s max(0, n.h)^p, where l and
 * h = unit(l + v) are unit vectors towards the light and halfway between it and the eye. */
float3 phong_color(Hit hit, int leaving_kind, int leaving, float3 ambient, real3 origin, real3 direction, CLR_SCENE_PARAMS)
{
    ClrMaterial material = materials[kind_material(hit.kind, hit.index, CLR_SCENE_ARGS)];
    real3 point = origin + hit.t * direction;
    real3 normal = kind_normal(hit.kind, hit.index, point, direction, CLR_SCENE_ARGS);
    float3 color = ambient;
    for (int i = 0; i < info.light_count; ++i) {
        real3 to_light = convert_real3(lights[i].position.xyz) - point;
        real distance = sqrt(dot3(to_light, to_light));
        if (!(distance > 0.0f))
            continue; /* a light at the point itself lights nothing there, as the sun */
        real3 light = to_light / distance;
        real cosine = dot3(normal, light);
        if (cosine <= 0.0f)
            continue; /* behind the surface: no shadow ray needed */
        if (occluded(point, light, distance, leaving_kind, leaving, CLR_SCENE_ARGS))
            continue;
        real3 half_vector = unit3(light - direction);
        real highlight = pow(fmax(dot3(normal, half_vector), (real)0.0f), (real)material.diffuse.w);
        color += lights[i].color.xyz *
                 (material.diffuse.xyz * (float)cosine + material.specular.xyz * (float)highlight);
    }
    return color;
}
#endif

/* The colour a surface shows at distance t along the ray: its colour before lighting
 * (kinds/kinds.cl), and for a kind that the sun lights, in sun mode, that colour scaled by
 * max(0, n.l) and by 0 when an opaque surface lies between the point and the sun. Shading
 * uses dot3() and unit3(), never the built-in dot(), length() or normalize(): their order,
 * FMAs and scaling are the implementation's, and Intel's CPU runtime and PoCL gave pixels one
 * display step apart; with + - * / and sqrt alone both give the same bytes. */
float3 surface_color(Hit hit, int leaving_kind, int leaving, real3 origin, real3 direction, CLR_SCENE_PARAMS)
{
    float3 color = kind_surface_color(hit.kind, hit.index, origin, direction, hit.t, CLR_SCENE_ARGS);
#if CLR_FEATURE_LIGHTS
    if (info.light_count > 0 && kind_is_lit(hit.kind))
        return phong_color(hit, leaving_kind, leaving, color, origin, direction, CLR_SCENE_ARGS);
#endif
#if CLR_FEATURE_SUN
    if (!info.lit || !kind_is_lit(hit.kind))
        return color;
    real3 point = origin + hit.t * direction;
    real3 normal = kind_normal(hit.kind, hit.index, point, direction, CLR_SCENE_ARGS);
    real3 to_sun = convert_real3(info.sun.xyz) - point;
    real sun_distance = sqrt(dot3(to_sun, to_sun));
    real3 light = to_sun / sun_distance;
    real cosine = dot3(normal, light);
    if (cosine <= 0.0f)
        return (float3)(0.0f); /* facing away: no shadow ray needed */
    return occluded(point, light, sun_distance, leaving_kind, leaving, CLR_SCENE_ARGS) ? (float3)(0.0f)
                                                                                      : color * (float)cosine;
#else
    return color;
#endif
}

/* Shades `hit` of the ray (origin, direction) after `reflections` mirror bounces. */
ShadeResult shade_hit(Hit hit, real3 origin, real3 direction, int reflections, CLR_SCENE_PARAMS)
{
    ShadeResult result;
    result.bounces = 0;
    result.color = info.background.xyz;
    if (hit.kind == CLR_HIT_NONE)
        return result;
    /* What its shadow and reflected rays leave (skip): the surface hit, and for a settled
     * triangle hit also the lowest other triangle at that edge or corner (CLR_SKIP_PAIR). */
    int leaving_kind = hit.kind;
    const int leaving = hit.index;
#if CLR_FEATURE_TRIANGLE_TIES
    /* A hit on a shared edge or corner is shaded as the lowest triangle there (triangle_ties).
     * The point lies in the plane of the triangle hit, but only to the band in the other's: a
     * shadow ray that skipped only the triangle shaded met the one hit again at t ~ 0 in double
     * (whose plane slack is below the rounding of float corners); one that skipped only the one
     * hit met the other a band's width away under narrow lenses; and where the one hit is the
     * lowest, the double kernel met a valley's other side again at t ~ 0. */
    if (hit.kind == CLR_HIT_TRIANGLE) {
        int other;
        hit.index = triangle_settled_index(hit.index, origin + hit.t * direction, hit.t, &other, CLR_SCENE_ARGS);
        leaving_kind = skip_kind_of_pair(leaving, other);
    }
#endif
#if CLR_FEATURE_MIRRORS
    if (kind_flags(hit.kind, hit.index, CLR_SCENE_ARGS) & CLR_SURFACE_MIRROR) {
        real3 point = origin + hit.t * direction;
        real3 normal = kind_normal(hit.kind, hit.index, point, direction, CLR_SCENE_ARGS);
        if (dot3(direction, normal) >= 0.0f) {
            result.color = (float3)(0.0f); /* the back of a mirror is black */
            return result;
        }
        if (reflections >= info.max_depth)
            return result; /* one reflection too many: background */
        result.bounces = 1;
#if CLR_FEATURE_LIGHTS
        result.weight = (float3)(1.0f); /* an ideal mirror: the reflection is all it shows */
        result.color = (float3)(0.0f);
#endif
        result.next_origin = point;
        result.next_direction = unit3(reflect_direction(direction, normal));
        result.leaving_kind = leaving_kind;
        result.leaving_index = leaving;
        return result;
    }
#endif
    result.color = surface_color(hit, leaving_kind, leaving, origin, direction, CLR_SCENE_ARGS);
#if CLR_FEATURE_LIGHTS
    /* A material with a mirror share k_m adds that share of the reflected ray's colour. */
    if (info.light_count > 0 && kind_is_lit(hit.kind)) {
        float3 mirror = materials[kind_material(hit.kind, hit.index, CLR_SCENE_ARGS)].mirror.xyz;
        if (mirror.x != 0.0f || mirror.y != 0.0f || mirror.z != 0.0f) {
            if (reflections >= info.max_depth) {
                result.color += mirror * info.background.xyz; /* one reflection too many */
                return result;
            }
            real3 point = origin + hit.t * direction;
            real3 normal = kind_normal(hit.kind, hit.index, point, direction, CLR_SCENE_ARGS);
            result.bounces = 1;
            result.weight = mirror;
            result.next_origin = point;
            result.next_direction = unit3(reflect_direction(direction, normal));
            result.leaving_kind = leaving_kind;
            result.leaving_index = leaving;
        }
    }
#endif
    return result;
}

#endif /* CLR_SHADE_CL */
