/* Stage 1: camera rays (docs/scene-format.md, Conventions: Camera). */
#ifndef CLR_RAYGEN_CL
#define CLR_RAYGEN_CL

#include "common/math.cl"
#include "shared/clr_types.h"

/* The unit-direction ray from the eye through point (col + ox, row + oy) of the image, with
 * ox, oy in [0, 1) inside pixel (col, row); row 0 is the top of the image, so the vertical
 * screen coordinate runs from +1 at the top to -1. */
Ray camera_ray_through(ClrCamera camera, int col, int row, float ox, float oy)
{
    real sx = 2.0f * ((real)col + ox) / (real)camera.width - 1.0f;
    real sy = 1.0f - 2.0f * ((real)row + oy) / (real)camera.height;
    real3 direction = convert_real3(camera.forward.xyz) + sx * convert_real3(camera.right.xyz) +
                      sy * convert_real3(camera.up.xyz);
    Ray ray;
    ray.origin = convert_real3(camera.eye.xyz);
    ray.direction = unit3(direction);
    return ray;
}

#if CLR_FEATURE_CLIP
/* The part of the primary ray along `direction` that the clip depths keep (docs/scene-format.md,
 * Near and far clipping): depths along the view direction from camera.eye.w to
 * camera.forward.w, as distances t_start < t < t_end along the unit direction. */
void clip_segment(ClrCamera camera, real3 direction, real* t_start, real* t_end)
{
    real depth_per_t = dot3(direction, convert_real3(camera.forward.xyz));
    *t_start = (real)camera.eye.w / depth_per_t;
    *t_end = (real)camera.forward.w / depth_per_t;
}
#endif

/* The float form of a ray, for buffers. */
ClrRay device_ray(Ray ray)
{
    ClrRay out;
    out.origin = (float4)(convert_float3(ray.origin), 0.0f);
    out.direction = (float4)(convert_float3(ray.direction), 0.0f);
    return out;
}

/* The ray through the centre of pixel (col, row). */
Ray camera_ray(ClrCamera camera, int col, int row)
{
    return camera_ray_through(camera, col, row, 0.5f, 0.5f);
}

#endif /* CLR_RAYGEN_CL */
