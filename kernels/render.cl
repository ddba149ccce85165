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
    for (int sample = 0; sample < camera.samples; ++sample) {
        float ox = clr_sample_offset_x(camera.frame_seed, col, row, sample, camera.samples);
        float oy = clr_sample_offset_y(camera.frame_seed, col, row, sample, camera.samples);
        Ray ray = camera_ray_through(camera, col, row, ox, oy);
        Hit hit = intersect_scene(ray.origin, ray.direction, INFINITY, CLR_HIT_NONE, -1, CLR_SCENE_ARGS);
        sum += trace_path(ray.origin, ray.direction, hit, CLR_SCENE_ARGS);
    }
    pixels[band_row * camera.width + col] = display_pixel(sum / (float)camera.samples);
}

/* The display bytes of 16 pixels, packed as RGBA words (alpha 255): color_to_byte() of the
 * mean of their samples' colours (the sums r, g, b over `samples`). */
CLR_PACKET_INLINE uint16 display_pixels16(float16 r, float16 g, float16 b, int samples)
{
    float n = (float)samples;
    uint16 rb = convert_uint16(floor(clamp(r / n, 0.0f, 1.0f) * 255.0f + 0.5f));
    uint16 gb = convert_uint16(floor(clamp(g / n, 0.0f, 1.0f) * 255.0f + 0.5f));
    uint16 bb = convert_uint16(floor(clamp(b / n, 0.0f, 1.0f) * 255.0f + 0.5f));
#if __ENDIAN_LITTLE__
    return rb | (gb << 8) | (bb << 16) | (uint16)(0xff000000u);
#else
    return (rb << 24) | (gb << 16) | (bb << 8) | (uint16)(0xffu);
#endif
}

/* Writes the first `lanes` of 16 packed pixels to out[0 .. lanes - 1]. */
CLR_PACKET_INLINE void store_pixels16(__global uchar4* out, uint16 packed, int lanes)
{
    __global uint* words = (__global uint*)out;
    if (lanes == 16) {
        vstore16(packed, 0, words);
        return;
    }
    uint w[16];
    vstore16(packed, 0, w);
    for (int lane = 0; lane < lanes; ++lane)
        words[lane] = w[lane];
}

/* Pixels col0 .. col0 + 15 of `row`, whose primary rays meet only objects of the tile list
 * items[first] .. items[end - 1], as packed display words. The rays are intersected together
 * (intersect_packet.cl); with flat shading their colours come from the same loop, otherwise
 * each lane's path is shaded by trace_path(). */
CLR_PACKET_INLINE uint16 render_row16(ClrCamera camera, real3 eye, int col0, int row, __global const uint* tile_items,
                    __global const float* item_nearest, __global const uint* item_rows, uint first, uint end,
                    CLR_SCENE_PARAMS)
{
    float16 rs = (float16)(0.0f), gs = (float16)(0.0f), bs = (float16)(0.0f); /* sums over samples */
    for (int sample = 0; sample < camera.samples; ++sample) {
        float16 ox = (float16)(0.5f), oy = (float16)(0.5f); /* one sample: the centre (clr_samples.h) */
        if (camera.samples > 1) {
            float oxs[16], oys[16];
            for (int lane = 0; lane < 16; ++lane) {
                oxs[lane] = clr_sample_offset_x(camera.frame_seed, col0 + lane, row, sample, camera.samples);
                oys[lane] = clr_sample_offset_y(camera.frame_seed, col0 + lane, row, sample, camera.samples);
            }
            ox = vload16(0, oxs);
            oy = vload16(0, oys);
        }
        Directions16 d = camera_rays16(camera, col0, row, ox, oy);
        real16 best_t;
        int16 best_kind, best_index;
        float16 r, g, b;
        intersect_tile16(eye, d, row, tile_items, item_nearest, item_rows, first, end, CLR_SCENE_ARGS, &best_t, &best_kind, &best_index,
                         &r, &g, &b);
#if CLR_FLAT_SHADING
        rs += r;
        gs += g;
        bs += b;
#else
#if CLR_LOOP_COLORS
        if (!any(best_kind == (int16)(CLR_HIT_SPHERE))) { /* no lane needs the sun */
            rs += r;
            gs += g;
            bs += b;
            continue;
        }
#endif
        real ts[16], xs[16], ys[16], zs[16];
        int kinds[16], indices[16];
        float rl[16], gl[16], bl[16];
#if CLR_LOOP_COLORS
        vstore16(r, 0, rl);
        vstore16(g, 0, gl);
        vstore16(b, 0, bl);
#endif
        vstore16(best_t, 0, ts);
        vstore16(best_kind, 0, kinds);
        vstore16(best_index, 0, indices);
        vstore16(d.x, 0, xs);
        vstore16(d.y, 0, ys);
        vstore16(d.z, 0, zs);
        for (int lane = 0; lane < 16; ++lane) {
#if CLR_LOOP_COLORS
            if (kinds[lane] != CLR_HIT_SPHERE)
                continue; /* its flat colour is in rl, gl, bl already */
#endif
            Hit hit;
            hit.t = ts[lane];
            hit.kind = kinds[lane];
            hit.index = indices[lane];
            real3 direction = (real3)(xs[lane], ys[lane], zs[lane]);
            float3 color = trace_path(eye, direction, hit, CLR_SCENE_ARGS);
            rl[lane] = color.x;
            gl[lane] = color.y;
            bl[lane] = color.z;
        }
        rs += vload16(0, rl);
        gs += vload16(0, gl);
        bs += vload16(0, bl);
#endif
    }
    return display_pixels16(rs, gs, bs, camera.samples);
}

/* The same as render, with screen-tile culling for the primary rays: work-item (x, y)
 * renders screen tile x of tile row first_row / CLR_TILE_SIZE + y, that is the rows of its
 * 16x16 pixels that lie in the band, 16 pixels of a row at a time (render_row16). A tile
 * that no object can reach is the background's colour throughout. Identical output to
 * render. */
__kernel void render_packets(ClrCamera camera, int first_row, int row_count, CLR_SCENE_PARAMS,
                             __global uchar4* pixels, __global const uint* tile_offsets,
                             __global const uint* tile_items, __global const float* item_nearest,
                             __global const uint* item_rows, int tiles_x)
{
    int tile_x = get_global_id(0);
    int tile_y = first_row / CLR_TILE_SIZE + (int)get_global_id(1);
    int col0 = tile_x * CLR_TILE_SIZE;
    int row_begin = max(first_row, tile_y * CLR_TILE_SIZE);
    int row_end = min(first_row + row_count, (tile_y + 1) * CLR_TILE_SIZE);
    if (col0 >= camera.width || row_begin >= row_end)
        return;
    int lanes = min(16, camera.width - col0);
    int tile = tile_y * tiles_x + tile_x;
    uint first = tile_offsets[tile], end = tile_offsets[tile + 1];
    __global uchar4* out = pixels + (row_begin - first_row) * camera.width + col0;
    if (first == end) {
        /* Every sample sees the background: the mean as render computes it, once. */
        float3 sum = (float3)(0.0f);
        for (int sample = 0; sample < camera.samples; ++sample)
            sum += info.background.xyz;
        float3 mean = sum / (float)camera.samples;
        uint16 packed = display_pixels16((float16)(mean.x), (float16)(mean.y), (float16)(mean.z), 1);
        for (int row = row_begin; row < row_end; ++row, out += camera.width)
            store_pixels16(out, packed, lanes);
        return;
    }
    real3 eye = convert_real3(camera.eye.xyz);
    for (int row = row_begin; row < row_end; ++row, out += camera.width)
        store_pixels16(out, render_row16(camera, eye, col0, row, tile_items, item_nearest, item_rows, first, end, CLR_SCENE_ARGS),
                       lanes);
}
