/* Stage 1: camera rays (SPEC 2, Camera). */

/* The unit-direction ray from the eye through point (col + ox, row + oy) of the image, with
 * ox, oy in [0, 1) inside pixel (col, row); row 0 is the top of the image, so the vertical
 * screen coordinate runs from +1 at the top to -1. */
ClrRay camera_ray_through(ClrCamera camera, int col, int row, float ox, float oy)
{
    float sx = 2.0f * ((float)col + ox) / (float)camera.width - 1.0f;
    float sy = 1.0f - 2.0f * ((float)row + oy) / (float)camera.height;
    float3 direction = camera.forward.xyz + sx * camera.right.xyz + sy * camera.up.xyz;
    ClrRay ray;
    ray.origin = (float4)(camera.eye.xyz, 0.0f);
    ray.direction = (float4)(unit3(direction), 0.0f);
    return ray;
}

/* The ray through the centre of pixel (col, row). */
ClrRay camera_ray(ClrCamera camera, int col, int row)
{
    return camera_ray_through(camera, col, row, 0.5f, 0.5f);
}

/* One work-item per pixel: writes the primary ray of pixel (x, y) to rays[y * width + x]. */
__kernel void raygen(ClrCamera camera, __global ClrRay* rays)
{
    int col = get_global_id(0);
    int row = get_global_id(1);
    if (col >= camera.width || row >= camera.height)
        return;
    rays[row * camera.width + col] = camera_ray(camera, col, row);
}
