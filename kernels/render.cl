/* The whole frame in one kernel: camera ray, then intersect and shade in a loop that
 * follows mirror reflections (no recursion in OpenCL C), then the display byte. It calls the
 * same functions as the stage kernels, which the tests check one by one. */

float3 trace_path(float3 origin, float3 direction, CLR_SCENE_PARAMS)
{
    int leaving_kind = CLR_HIT_NONE;
    int leaving_index = -1;
    /* shade_hit() stops bouncing once `reflections` reaches info.max_depth. */
    for (int reflections = 0;; ++reflections) {
        ClrHit hit = intersect_scene(origin, direction, INFINITY, leaving_kind, leaving_index, CLR_SCENE_ARGS);
        ShadeResult result = shade_hit(hit, origin, direction, reflections, CLR_SCENE_ARGS);
        if (!result.bounces)
            return result.color;
        origin = result.next_origin;
        direction = result.next_direction;
        leaving_kind = result.leaving_kind;
        leaving_index = result.leaving_index;
    }
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
    float3 color = trace_path(ray.origin.xyz, ray.direction.xyz, CLR_SCENE_ARGS);
    pixels[band_row * camera.width + col] =
        (uchar4)(color_to_byte(color.x), color_to_byte(color.y), color_to_byte(color.z), 255);
}
