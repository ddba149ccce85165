/* The brute-force program: render, where every pixel's rays test every object. It is the
 * tests' general reference for render_packets, and what RendererOptions::screen_tiles = false
 * renders with. */
#include "common/math.cl"
#include "common/scene_params.cl"
#include "intersect.cl"
#include "raygen.cl"
#include "shared/clr_samples.h"
#include "shared/clr_types.h"
#include "trace.cl"

/* One work-item per pixel of a band of rows starting at `first_row` (the whole image when
 * it fits in one buffer): writes the display colour of pixel (x, first_row + y) to
 * pixels[y * width + x] as RGBA bytes (alpha 255); with CLR_FEATURE_FLOAT_OUTPUT as a float4
 * (the linear mean colour and the fraction of samples that hit an object) instead. */
/* vec_type_hint (a standard hint, which PoCL ignores) keeps Intel's CPU runtime from
 * vectorising this kernel across work-items: with AVX-512 its vectorised form of the double
 * kernels with sun and mirrors gave a fifth of the pixels different colours from the same
 * kernel unvectorised (or vectorised for AVX2), from PoCL and from render_packets
 * (docs/opencl-devices.md). render is the tests' brute-force reference, not the CLI's path. */
__kernel __attribute__((vec_type_hint(float4))) void render(ClrCamera camera, int first_row, int row_count,
                                                             CLR_SCENE_PARAMS, __global uchar4* pixels)
{
    int col = get_global_id(0);
    int band_row = get_global_id(1);
    if (col >= camera.width || band_row >= row_count)
        return;
    int row = first_row + band_row;
    /* The mean of the pixel's samples (clr_samples.h), in display values. */
    float3 sum = (float3)(0.0f);
#if CLR_FEATURE_FLOAT_OUTPUT
    float hit_count = 0.0f; /* samples that hit an object: the pixel's coverage */
#endif
    for (int sample = 0; sample < camera.samples; ++sample) {
        float ox = clr_sample_offset_x(camera.frame_seed, col, row, sample, camera.samples);
        float oy = clr_sample_offset_y(camera.frame_seed, col, row, sample, camera.samples);
        Ray ray = camera_ray_through(camera, col, row, ox, oy);
#if CLR_FEATURE_CLIP
        Hit hit = nearest_in_view(camera, ray, CLR_SCENE_ARGS);
#else
        Hit hit = intersect_scene(ray.origin, ray.direction, INFINITY, CLR_HIT_NONE, -1, CLR_SCENE_ARGS);
#endif
        sum += trace_path(ray.origin, ray.direction, hit, CLR_SCENE_ARGS);
#if CLR_FEATURE_FLOAT_OUTPUT
        hit_count += hit.kind != CLR_HIT_NONE ? 1.0f : 0.0f;
#endif
    }
#if CLR_FEATURE_FLOAT_OUTPUT
    float n = (float)camera.samples;
    ((__global float4*)pixels)[band_row * camera.width + col] = (float4)(sum / n, hit_count / n);
#else
    pixels[band_row * camera.width + col] = display_pixel(sum / (float)camera.samples);
#endif
}

