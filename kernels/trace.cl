/* A primary ray's path to its colour: intersect and shade in a loop that follows mirror
 * reflections (no recursion in OpenCL C), then the display byte. Both render kernels call
 * these functions, which are the stage kernels' (the tests check those one by one). */
#ifndef CLR_TRACE_CL
#define CLR_TRACE_CL

#include "common/math.cl"
#include "common/scene_params.cl"
#include "intersect.cl"
#include "raygen.cl"
#include "shade.cl"
#include "shared/clr_types.h"

/* The colour seen along a primary ray whose nearest hit is `hit`. */
float3 trace_path(real3 origin, real3 direction, Hit hit, CLR_SCENE_PARAMS)
{
#if CLR_FEATURE_LIGHTS
    /* Each surface adds its colour, scaled by the mirror shares of the surfaces before it. */
    float3 sum = (float3)(0.0f), weight = (float3)(1.0f);
#endif
    /* shade_hit() stops bouncing once `reflections` reaches info.max_depth. */
    for (int reflections = 0;; ++reflections) {
        ShadeResult result = shade_hit(hit, origin, direction, reflections, CLR_SCENE_ARGS);
#if CLR_FEATURE_LIGHTS
        sum += weight * result.color;
        if (!result.bounces)
            return sum;
        weight *= result.weight;
#else
        if (!result.bounces)
            return result.color;
#endif
        origin = result.next_origin;
        direction = result.next_direction;
        hit = intersect_scene(origin, direction, INFINITY, result.leaving_kind, result.leaving_index, CLR_SCENE_ARGS);
    }
}

#if CLR_FEATURE_CLIP
/* The nearest hit of a primary ray among the depths the camera keeps: the search starts on the
 * near plane, at eye + t_start d, and ends at the far one; the hit's t is the eye's again. */
Hit nearest_in_view(ClrCamera camera, Ray ray, CLR_SCENE_PARAMS)
{
    real t_start, t_end;
    clip_segment(camera, ray.direction, &t_start, &t_end);
    Hit hit = intersect_scene(ray.origin + t_start * ray.direction, ray.direction, t_end - t_start, CLR_HIT_NONE, -1,
                              CLR_SCENE_ARGS);
    if (hit.kind != CLR_HIT_NONE)
        hit.t += t_start;
    return hit;
}
#endif

uchar4 display_pixel(float3 color)
{
    return (uchar4)(color_to_byte(color.x), color_to_byte(color.y), color_to_byte(color.z), 255);
}

#endif /* CLR_TRACE_CL */
