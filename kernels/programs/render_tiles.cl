/* The program clrender renders with: render_packets alone, so that building it (and asking
 * for its binary, to cache it) compiles only the kernel the command line runs. */
#include "common/math.cl"
#include "common/scene_params.cl"
#include "packet/bvh_entries.cl"
#include "packet/packet_types.cl"
#include "packet/render_row16.cl"
#include "shared/clr_types.h"

/* The same as render, with screen-tile culling for the primary rays: work-item (x, y)
 * renders screen tile x of tile row first_row / CLR_TILE_SIZE + y, that is the rows of its
 * 16x16 pixels that lie in the band, 16 pixels of a row at a time (render_row16), or where
 * packets walk the BVH 4x4 pixels at a time (render_block16), from entries the tile finds once
 * (packet/bvh_entries.cl). A tile that no object can reach is the background's colour
 * throughout (known from its list; where packets walk the BVH instead, info.primary_bvh, every
 * tile is traced). Identical output to render. With CLR_FEATURE_FLOAT_OUTPUT, `pixels` holds
 * a float4 per pixel instead (CLR_PIXEL). */
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
    TileItems items;
    items.items = tile_items;
    items.nearest = item_nearest;
    items.rows = item_rows;
    items.first = tile_offsets[tile];
    items.end = tile_offsets[tile + 1];
    __global CLR_PIXEL* out = (__global CLR_PIXEL*)pixels + (row_begin - first_row) * camera.width + col0;
#if CLR_FEATURE_PLANES
    bool no_plane = info.plane_count == 0; /* planes are in no tile, and may cross any */
#else
    bool no_plane = true;
#endif
#if CLR_FEATURE_BVH
    bool listed = !info.primary_bvh; /* walking the BVH, tiles have no lists */
#else
    bool listed = true;
#endif
    if (listed && items.first == items.end && no_plane) {
        /* Every sample sees the background: the mean as render computes it, once. */
        float3 sum = (float3)(0.0f);
        for (int sample = 0; sample < camera.samples; ++sample)
            sum += info.background.xyz;
        float3 mean = sum / (float)camera.samples;
#if CLR_FEATURE_FLOAT_OUTPUT
        for (int row = row_begin; row < row_end; ++row, out += camera.width)
            for (int lane = 0; lane < lanes; ++lane)
                out[lane] = (float4)(mean, 0.0f); /* no sample hit an object */
#else
        uint16 packed = display_pixels16((float16)(mean.x), (float16)(mean.y), (float16)(mean.z), 1);
        for (int row = row_begin; row < row_end; ++row, out += camera.width)
            store_pixels16(out, packed, lanes);
#endif
        return;
    }
    real3 eye = convert_real3(camera.eye.xyz);
    BvhEntries entries; /* filled where packets walk the BVH; never a null pointer: Oclgrind's
                           compiler made of a null here an llvm.assume it cannot run */
    entries.count = 0;
    items.entries = &entries;
#if CLR_FEATURE_BVH
    if (info.primary_bvh) { /* 4x4 blocks, whose rays spread less through the BVH than a row's */
        TileFrustum frustum = tile_frustum(camera, col0, col0 + lanes, row_begin, row_end);
        bvh_entries(&frustum, &entries, CLR_SCENE_ARGS);
        for (int row0 = row_begin; row0 < row_end; row0 += 4, out += 4 * camera.width) {
            int rows = min(4, row_end - row0);
            for (int c = 0; c < lanes; c += 4) {
#if CLR_FEATURE_FLOAT_OUTPUT
                render_linear_block16(out + c, min(4, lanes - c), rows, camera, eye, col0 + c, row0, items,
                                      CLR_SCENE_ARGS);
#else
                store_block16(out + c, camera.width, render_block16(camera, eye, col0 + c, row0, items, CLR_SCENE_ARGS),
                              min(4, lanes - c), rows);
#endif
            }
        }
        return;
    }
#endif
    for (int row = row_begin; row < row_end; ++row, out += camera.width)
#if CLR_FEATURE_FLOAT_OUTPUT
        render_linear_row16(out, lanes, camera, eye, col0, row, items, CLR_SCENE_ARGS);
#else
        store_pixels16(out, render_row16(camera, eye, col0, row, items, CLR_SCENE_ARGS), lanes);
#endif
}
