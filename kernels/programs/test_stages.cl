/* The test program: the stage kernels raygen, intersect and shade, which the tests run one by
 * one against the host reference (tests/support/stage_runner.cpp), and struct_layout
 * (tests/device/struct_layout_test.cpp). clrender itself never builds it. */
#include "common/math.cl"
#include "common/scene_params.cl"
#include "intersect.cl"
#include "layout.cl"
#include "raygen.cl"
#include "shade.cl"
#include "shared/clr_types.h"

/* One work-item per pixel: writes the primary ray of pixel (x, y) to rays[y * width + x]. */
__kernel void raygen(ClrCamera camera, __global ClrRay* rays)
{
    int col = get_global_id(0);
    int row = get_global_id(1);
    if (col >= camera.width || row >= camera.height)
        return;
    rays[row * camera.width + col] = device_ray(camera_ray(camera, col, row));
}

/* One work-item per ray: writes the nearest hit of rays[i] to hits[i], for i < ray_count. */
__kernel void intersect(__global const ClrRay* rays, int ray_count, CLR_SCENE_PARAMS, __global ClrHit* hits)
{
    int i = get_global_id(0);
    if (i >= ray_count)
        return;
    Hit hit = intersect_scene(convert_real3(rays[i].origin.xyz), convert_real3(rays[i].direction.xyz), INFINITY,
                              CLR_HIT_NONE, -1, CLR_SCENE_ARGS);
    hits[i] = device_hit(hit);
}

/* One work-item per ray: shades hits[i] of rays[i] as seen after `reflections` bounces.
 * Writes colors[i] = (rgb, 1) when the path ends there, or (0, 0, 0, 0) and the reflected
 * ray to next_rays[i] when it continues. */
__kernel void shade(__global const ClrRay* rays, __global const ClrHit* hits, int ray_count, int reflections,
                    CLR_SCENE_PARAMS, __global float4* colors, __global ClrRay* next_rays)
{
    int i = get_global_id(0);
    if (i >= ray_count)
        return;
    Hit hit;
    hit.t = hits[i].t;
    hit.kind = hits[i].kind;
    hit.index = hits[i].index;
    ShadeResult result = shade_hit(hit, convert_real3(rays[i].origin.xyz), convert_real3(rays[i].direction.xyz),
                                   reflections, CLR_SCENE_ARGS);
    colors[i] = result.bounces ? (float4)(0.0f) : (float4)(result.color, 1.0f);
    ClrRay next;
    next.origin = (float4)(result.bounces ? convert_float3(result.next_origin) : (float3)(0.0f), 0.0f);
    next.direction = (float4)(result.bounces ? convert_float3(result.next_direction) : (float3)(0.0f), 0.0f);
    next_rays[i] = next;
}
