/* The whole frame in one kernel: camera ray, then intersect and shade in a loop that
 * follows mirror reflections (no recursion in OpenCL C), then the display byte. It calls the
 * same functions as the stage kernels, which the tests check one by one. */

/* The colour seen along a primary ray whose nearest hit is `hit`. */
float3 trace_path(float3 origin, float3 direction, ClrHit hit, CLR_SCENE_PARAMS)
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
    ClrRay ray = camera_ray(camera, col, first_row + band_row);
    ClrHit hit = intersect_scene(ray.origin.xyz, ray.direction.xyz, INFINITY, CLR_HIT_NONE, -1, CLR_SCENE_ARGS);
    float3 color = trace_path(ray.origin.xyz, ray.direction.xyz, hit, CLR_SCENE_ARGS);
    pixels[band_row * camera.width + col] = display_pixel(color);
}

/* The same as render, with screen-tile culling for the primary rays: pixel (x, y) tests only
 * the objects binned to its tile (see intersect_tile). Identical output. */
__kernel void render_tiled(ClrCamera camera, int first_row, int row_count, CLR_SCENE_PARAMS,
                           __global uchar4* pixels, __global const uint* tile_offsets,
                           __global const uint* tile_items, __global const float* item_nearest, int tiles_x)
{
    int col = get_global_id(0);
    int band_row = get_global_id(1);
    if (col >= camera.width || band_row >= row_count)
        return;
    int row = first_row + band_row;
    int tile = (row / CLR_TILE_SIZE) * tiles_x + col / CLR_TILE_SIZE;
    ClrRay ray = camera_ray(camera, col, row);
    ClrHit hit = intersect_tile(ray.origin.xyz, ray.direction.xyz, tile_items, item_nearest, tile_offsets[tile],
                                tile_offsets[tile + 1], CLR_SCENE_ARGS);
    float3 color = trace_path(ray.origin.xyz, ray.direction.xyz, hit, CLR_SCENE_ARGS);
    pixels[band_row * camera.width + col] = display_pixel(color);
}
