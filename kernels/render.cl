/* The whole frame in one kernel: camera ray, then intersect and shade in a loop that
 * follows mirror reflections (no recursion in OpenCL C), then the display byte. It calls the
 * same functions as the stage kernels, which the tests check one by one. */

/* The colour seen along a primary ray whose nearest hit is `hit`. */
float3 trace_path(real3 origin, real3 direction, Hit hit, CLR_SCENE_PARAMS)
{
    /* shade_hit() stops bouncing once `reflections` reaches info.max_depth. */
    for (int reflections = 0;; ++reflections) {
        ShadeResult result = shade_hit(hit, origin, direction, reflections, CLR_SCENE_ARGS);
        if (!result.bounces)
            return result.color;
        origin = result.next_origin;
        direction = result.next_direction;
        hit = intersect_scene(origin, direction, INFINITY, result.leaving_kind, result.leaving_index, CLR_SCENE_ARGS);
    }
}

uchar4 display_pixel(float3 color)
{
    return (uchar4)(color_to_byte(color.x), color_to_byte(color.y), color_to_byte(color.z), 255);
}

/* One work-item per pixel of a band of rows starting at `first_row` (the whole image when
 * it fits in one buffer): writes the display colour of pixel (x, first_row + y) to
 * pixels[y * width + x] as RGBA bytes (alpha 255). */
__kernel void render(ClrCamera camera, int first_row, int row_count, CLR_SCENE_PARAMS, __global uchar4* pixels)
{
    int col = get_global_id(0);
    int band_row = get_global_id(1);
    if (col >= camera.width || band_row >= row_count)
        return;
    int row = first_row + band_row;
    /* The mean of the pixel's samples (clr_samples.h), in display values. */
    float3 sum = (float3)(0.0f);
    for (int sample = 0; sample < camera.samples; ++sample) {
        float ox = clr_sample_offset_x(camera.frame_seed, col, row, sample, camera.samples);
        float oy = clr_sample_offset_y(camera.frame_seed, col, row, sample, camera.samples);
        Ray ray = camera_ray_through(camera, col, row, ox, oy);
        Hit hit = intersect_scene(ray.origin, ray.direction, INFINITY, CLR_HIT_NONE, -1, CLR_SCENE_ARGS);
        sum += trace_path(ray.origin, ray.direction, hit, CLR_SCENE_ARGS);
    }
    pixels[band_row * camera.width + col] = display_pixel(sum / (float)camera.samples);
}

/* The same as render, with screen-tile culling for the primary rays and 16 pixels per
 * work-item: work-item (x, y) renders pixels 16x .. 16x + 15 of row first_row + y, which lie
 * in one screen tile. Their primary rays are intersected together with the tile's objects
 * only (intersect_packet.cl), then shaded one by one. Identical output to render. */
__kernel void render_packets(ClrCamera camera, int first_row, int row_count, CLR_SCENE_PARAMS,
                             __global uchar4* pixels, __global const uint* tile_offsets,
                             __global const uint* tile_items, __global const float* item_nearest, int tiles_x)
{
    int col0 = get_global_id(0) * 16;
    int band_row = get_global_id(1);
    if (col0 >= camera.width || band_row >= row_count)
        return;
    int row = first_row + band_row;
    int tile = (row / CLR_TILE_SIZE) * tiles_x + col0 / CLR_TILE_SIZE;
    real3 eye = convert_real3(camera.eye.xyz);
    uint first = tile_offsets[tile], end = tile_offsets[tile + 1];
    float rs[16], gs[16], bs[16];  /* per lane: the sum of its samples' colours */
    for (int lane = 0; lane < 16; ++lane)
        rs[lane] = gs[lane] = bs[lane] = 0.0f;
    for (int sample = 0; sample < camera.samples; ++sample) {
        float oxs[16], oys[16];
        for (int lane = 0; lane < 16; ++lane) {
            oxs[lane] = clr_sample_offset_x(camera.frame_seed, col0 + lane, row, sample, camera.samples);
            oys[lane] = clr_sample_offset_y(camera.frame_seed, col0 + lane, row, sample, camera.samples);
        }
        Directions16 d = camera_rays16(camera, col0, row, vload16(0, oxs), vload16(0, oys));
        real16 best_t;
        int16 best_kind, best_index;
        intersect_tile16(eye, d, tile_items, item_nearest, first, end, CLR_SCENE_ARGS, &best_t, &best_kind, &best_index);

        real ts[16], xs[16], ys[16], zs[16];
        int kinds[16], indices[16];
        vstore16(best_t, 0, ts);
        vstore16(best_kind, 0, kinds);
        vstore16(best_index, 0, indices);
        vstore16(d.x, 0, xs);
        vstore16(d.y, 0, ys);
        vstore16(d.z, 0, zs);
        for (int lane = 0; lane < 16; ++lane) {
            Hit hit;
            hit.t = ts[lane];
            hit.kind = kinds[lane];
            hit.index = indices[lane];
            real3 direction = (real3)(xs[lane], ys[lane], zs[lane]);
            float3 color = trace_path(eye, direction, hit, CLR_SCENE_ARGS);
            rs[lane] += color.x;
            gs[lane] += color.y;
            bs[lane] += color.z;
        }
    }
    int lanes = min(16, camera.width - col0);
    /* color_to_byte() for 16 pixels at once */
    float samples = (float)camera.samples;
    uchar16 r = convert_uchar16(floor(clamp(vload16(0, rs) / samples, 0.0f, 1.0f) * 255.0f + 0.5f));
    uchar16 g = convert_uchar16(floor(clamp(vload16(0, gs) / samples, 0.0f, 1.0f) * 255.0f + 0.5f));
    uchar16 b = convert_uchar16(floor(clamp(vload16(0, bs) / samples, 0.0f, 1.0f) * 255.0f + 0.5f));
    uchar rb[16], gb[16], bb[16];
    vstore16(r, 0, rb);
    vstore16(g, 0, gb);
    vstore16(b, 0, bb);
    __global uchar4* out = pixels + band_row * camera.width + col0;
    for (int lane = 0; lane < lanes; ++lane)
        out[lane] = (uchar4)(rb[lane], gb[lane], bb[lane], 255);
}
