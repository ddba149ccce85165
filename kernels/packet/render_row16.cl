/* 16 pixels of one row of a screen tile at a time, for render_packets: their primary rays
 * are intersected together (intersect_packet.cl) and coloured by the program's shading mode
 * (shading_modes.cl), then packed as display words. */
#ifndef CLR_PACKET_RENDER_ROW16_CL
#define CLR_PACKET_RENDER_ROW16_CL

#include "common/math.cl"
#include "common/rgba_words.cl"
#include "common/scene_params.cl"
#include "kinds/kinds.cl"
#include "packet/intersect_packet.cl"
#include "packet/lane_masks.cl"
#include "packet/lanes16.cl"
#include "packet/packet_types.cl"
#include "packet/settled16.cl"
#include "packet/shading_modes.cl"
#include "packet/sunlit16.cl"
#include "shared/clr_samples.h"
#include "shared/clr_types.h"
#include "trace.cl"

/* What render_packets writes per pixel: RGBA bytes, or in the float output mode a float4. */
#if CLR_FEATURE_FLOAT_OUTPUT
#define CLR_PIXEL float4
#else
#define CLR_PIXEL uchar4
#endif

/* color_to_byte() of 16 channel values: the conversion truncates, which for the
 * non-negative clamp(c, 0, 1) * 255 + 0.5 is the floor color_to_byte() takes. PoCL computes
 * floor() of 16 lanes in a dozen instructions; with three channels that was a tenth of a
 * small scene's frame (docs/benchmarks.md, Packet fixed costs). */
CLR_PACKET_INLINE uint16 display_bytes16(float16 c)
{
    return convert_uint16(clamp(c, 0.0f, 1.0f) * 255.0f + 0.5f);
}

/* The display bytes of 16 pixels, packed as RGBA words (alpha 255): color_to_byte() of the
 * mean of their samples' colours (the sums r, g, b over `samples`). One sample's sum is its
 * mean: dividing by 1 changes no bit, and three divisions are a packet's dearest arithmetic. */
CLR_PACKET_INLINE uint16 display_pixels16(float16 r, float16 g, float16 b, int samples)
{
    if (samples != 1) {
        float n = (float)samples;
        r = r / n;
        g = g / n;
        b = b / n;
    }
    return CLR_RGBA_OPAQUE(display_bytes16(r), display_bytes16(g), display_bytes16(b));
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

/* Where in their pixels the 16 rays of sample `sample` lie (clr_samples.h). */
CLR_PACKET_INLINE void sample_offsets16(ClrCamera camera, LanePixels16 pixels, int sample, float16* ox, float16* oy)
{
    *ox = (float16)(0.5f); /* one sample: the centre */
    *oy = (float16)(0.5f);
    if (camera.samples > 1) {
        float oxs[16], oys[16];
        int cols[16], rows[16];
        vstore16(pixels.col, 0, cols);
        vstore16(pixels.row, 0, rows);
        for (int lane = 0; lane < 16; ++lane) {
            oxs[lane] = clr_sample_offset_x(camera.frame_seed, cols[lane], rows[lane], sample, camera.samples);
            oys[lane] = clr_sample_offset_y(camera.frame_seed, cols[lane], rows[lane], sample, camera.samples);
        }
        *ox = vload16(0, oxs);
        *oy = vload16(0, oys);
    }
}

/* The colours of 16 rays from the eye with nearest hits `hits`, each path shaded by
 * trace_path(). Given `flat` (the intersection loop's flat colours), only lanes on lit kinds
 * (kind_is_lit()) are traced and the others keep their flat colour; without (0), every lane
 * is traced. */
CLR_PACKET_INLINE Colors16 traced_colors16(real3 eye, Directions16 d, Hits16 hits, const Colors16* flat,
                                           CLR_SCENE_PARAMS)
{
    Lanes16 lanes;
    unpack_lanes16(d, hits, flat, &lanes);
    for (int lane = 0; lane < 16; ++lane) {
        if (flat && !kind_is_lit(lanes.kind[lane]))
            continue; /* its flat colour is in lanes.r, g, b already */
        Hit hit;
        hit.t = lanes.t[lane];
        hit.kind = lanes.kind[lane];
        hit.index = lanes.index[lane];
        real3 direction = (real3)(lanes.x[lane], lanes.y[lane], lanes.z[lane]);
        set_lane_color16(&lanes, lane, trace_path(eye, direction, hit, CLR_SCENE_ARGS));
    }
    return lane_colors16(&lanes);
}

/* The colours of 16 rays from the eye with nearest hits `hits`, in the program's shading mode
 * (shading_modes.cl). `flat` holds the intersection loop's flat colours (CLR_LOOP_COLORS). */
#if CLR_FLAT_SHADING
/* Flat: the loop's colours are the pixels' colours (a lane on a shared mesh edge or corner
 * takes the colour of the triangle it settles on, where that can differ). */
CLR_PACKET_INLINE Colors16 shaded_colors16(real3 eye, Directions16 d, Hits16 hits, Colors16 flat, CLR_SCENE_PARAMS)
{
#if CLR_FEATURE_TRIANGLE_TIES && CLR_FEATURE_TRIANGLES
    return settled_flat_colors16(eye, d, hits, flat, CLR_SCENE_ARGS);
#else
    return flat;
#endif
}
#elif CLR_LOOP_COLORS
/* Sun without mirrors: the loop's flat colours, with lanes on lit kinds lit one by one. */
CLR_PACKET_INLINE Colors16 shaded_colors16(real3 eye, Directions16 d, Hits16 hits, Colors16 flat, CLR_SCENE_PARAMS)
{
    if (!any_lanes16(lit_lanes16(hits.kind))) /* no lane needs the sun */
        return flat;
#if CLR_SUN_PACKETS
    return sunlit_colors16(eye, d, hits, flat, CLR_SCENE_ARGS);
#else
    return traced_colors16(eye, d, hits, &flat, CLR_SCENE_ARGS);
#endif
}
#else
/* Mirrors: every lane's path is traced (the loop gives no flat colours). */
CLR_PACKET_INLINE Colors16 shaded_colors16(real3 eye, Directions16 d, Hits16 hits, Colors16 flat, CLR_SCENE_PARAMS)
{
    return traced_colors16(eye, d, hits, 0, CLR_SCENE_ARGS);
}
#endif

/* The sums of the samples' colours of the lanes' pixels, whose primary rays meet only objects
 * of `tile`; a tile's list is searched for pixels of `row` (row_pixels16()), where the packets
 * walk the BVH the pixels may be any (block_pixels16()). With CLR_FEATURE_FLOAT_OUTPUT,
 * `hit_counts` receives how many of each pixel's samples hit an object (its coverage,
 * docs/command-line.md, HDR and alpha outputs); otherwise it is not touched. */
CLR_PACKET_INLINE Colors16 sample_sums16(ClrCamera camera, real3 eye, LanePixels16 pixels, int row, TileItems tile,
                                         float16* hit_counts, CLR_SCENE_PARAMS)
{
#if CLR_FEATURE_FLOAT_OUTPUT
    *hit_counts = (float16)(0.0f);
#endif
    Colors16 sums;
    sums.r = sums.g = sums.b = (float16)(0.0f);
    for (int sample = 0; sample < camera.samples; ++sample) {
        float16 ox, oy;
        sample_offsets16(camera, pixels, sample, &ox, &oy);
        Directions16 d = camera_rays16(camera, pixels, ox, oy);
        Hits16 hits;
#if CLR_FEATURE_CLIP
        /* Clipped rays start on the near plane, each at its own point: lane by lane. */
        clipped_hits16(camera, eye, d, row, tile, &hits, CLR_SCENE_ARGS);
        Colors16 colors = traced_colors16(eye, d, hits, 0, CLR_SCENE_ARGS);
#else
        Colors16 flat;
        intersect_tile16(eye, d, row, tile, CLR_SCENE_ARGS, &hits, &flat);
        Colors16 colors = shaded_colors16(eye, d, hits, flat, CLR_SCENE_ARGS);
#endif
        sums.r += colors.r;
        sums.g += colors.g;
        sums.b += colors.b;
#if CLR_FEATURE_FLOAT_OUTPUT
        *hit_counts += select((float16)(0.0f), (float16)(1.0f), hits.kind != (int16)(CLR_HIT_NONE));
#endif
    }
    return sums;
}

/* Pixels col0 .. col0 + 15 of `row`, whose primary rays meet only objects of `tile`, as
 * packed display words: the mean of their samples' colours. */
CLR_PACKET_INLINE uint16 render_row16(ClrCamera camera, real3 eye, int col0, int row, TileItems tile, CLR_SCENE_PARAMS)
{
    float16 unused;
    Colors16 sums = sample_sums16(camera, eye, row_pixels16(col0, row), row, tile, &unused, CLR_SCENE_ARGS);
    return display_pixels16(sums.r, sums.g, sums.b, camera.samples);
}

#if CLR_FEATURE_BVH
/* The 4x4 block of pixels from (col0, row0), as render_row16() renders a row, for packets that
 * walk the BVH (no list to cull by row). */
CLR_PACKET_INLINE uint16 render_block16(ClrCamera camera, real3 eye, int col0, int row0, TileItems tile,
                                        CLR_SCENE_PARAMS)
{
    float16 unused;
    Colors16 sums = sample_sums16(camera, eye, block_pixels16(col0, row0), -1, tile, &unused, CLR_SCENE_ARGS);
    return display_pixels16(sums.r, sums.g, sums.b, camera.samples);
}

/* Writes the first `cols` columns of the first `rows` rows of a 4x4 block of packed pixels
 * (lane 4 r + c at row r, column c) to `out`, rows `width` pixels apart. */
CLR_PACKET_INLINE void store_block16(__global uchar4* out, int width, uint16 packed, int cols, int rows)
{
    __global uint* words = (__global uint*)out;
    uint w[16];
    vstore16(packed, 0, w);
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c)
            words[r * width + c] = w[4 * r + c];
}
#endif

#if CLR_FEATURE_FLOAT_OUTPUT
/* The float output mode (docs/command-line.md, HDR and alpha outputs): per pixel the mean of
 * its samples' colours, linear and unclamped (the very value display_pixels16() turns into
 * bytes), and the fraction of its samples that hit an object. Writes lane stride * r + c to
 * out[r * width + c], for the first `rows` rows and `cols` columns: a row of 16 (stride 16)
 * or a 4x4 block (stride 4). */
CLR_PACKET_INLINE void store_linear16(__global float4* out, int width, int stride, int cols, int rows, Colors16 sums,
                                      float16 hit_counts, int samples)
{
    float n = (float)samples;
    float r[16], g[16], b[16], a[16];
    vstore16(sums.r / n, 0, r);
    vstore16(sums.g / n, 0, g);
    vstore16(sums.b / n, 0, b);
    vstore16(hit_counts / n, 0, a);
    for (int row = 0; row < rows; ++row)
        for (int col = 0; col < cols; ++col) {
            int lane = stride * row + col;
            out[row * width + col] = (float4)(r[lane], g[lane], b[lane], a[lane]);
        }
}

/* Pixels col0 .. col0 + 15 of `row` in the float output mode, written to out[0 .. lanes - 1]. */
CLR_PACKET_INLINE void render_linear_row16(__global float4* out, int lanes, ClrCamera camera, real3 eye, int col0,
                                           int row, TileItems tile, CLR_SCENE_PARAMS)
{
    float16 hit_counts;
    Colors16 sums = sample_sums16(camera, eye, row_pixels16(col0, row), row, tile, &hit_counts, CLR_SCENE_ARGS);
    store_linear16(out, camera.width, 16, lanes, 1, sums, hit_counts, camera.samples);
}

#if CLR_FEATURE_BVH
/* The 4x4 block from (col0, row0) in the float output mode, its first `cols` columns of its
 * first `rows` rows written to `out`, rows camera.width pixels apart. */
CLR_PACKET_INLINE void render_linear_block16(__global float4* out, int cols, int rows, ClrCamera camera, real3 eye,
                                             int col0, int row0, TileItems tile, CLR_SCENE_PARAMS)
{
    float16 hit_counts;
    Colors16 sums = sample_sums16(camera, eye, block_pixels16(col0, row0), -1, tile, &hit_counts, CLR_SCENE_ARGS);
    store_linear16(out, camera.width, 4, cols, rows, sums, hit_counts, camera.samples);
}
#endif
#endif

#endif /* CLR_PACKET_RENDER_ROW16_CL */
