/* A primary ray's path to its colour: intersect and shade in a loop that follows mirror
 * reflections (no recursion in OpenCL C), then the display byte. Both render kernels call
 * these functions, which are the stage kernels' (the tests check those one by one). */
#ifndef CLR_TRACE_CL
#define CLR_TRACE_CL

#include "common/math.cl"
#include "common/scene_params.cl"
#include "intersect.cl"
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

uchar4 display_pixel(float3 color)
{
    return (uchar4)(color_to_byte(color.x), color_to_byte(color.y), color_to_byte(color.z), 255);
}

#endif /* CLR_TRACE_CL */
