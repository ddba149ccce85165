#include "render/device_camera.h"

#include <algorithm>
#include <cmath>

#include "render/device_structs.h"

namespace clr {

ClrCamera make_device_camera(const Vec3& eye, const Vec3& lookat, const Vec3& up, double fov_degrees, int width,
                             int height) {
    const double kPi = 3.14159265358979323846;
    // Unit vectors before any cross product: `up` and eye - lookat may have any finite length
    // (normalize() copes), but a cross product of a 1e300-long `up` could overflow.
    Vec3 w = normalize(eye - lookat);            // towards the viewer
    Vec3 u = normalize(cross(normalize(up), w));  // screen right
    Vec3 v = cross(w, u);              // screen up
    // The field of view spans the larger dimension; pixels are square.
    double tan_half = std::tan(fov_degrees * kPi / 360.0);
    double larger = std::max(width, height);
    double half_width = tan_half * width / larger;
    double half_height = tan_half * height / larger;

    ClrCamera camera{};
    camera.eye = to_float4(eye);
    camera.forward = to_float4(-w);
    camera.right = to_float4(u * half_width);
    camera.up = to_float4(v * half_height);
    camera.width = width;
    camera.height = height;
    camera.samples = 1;  // the pixel centre; the renderer sets the scene's sampling
    camera.frame_seed = 0;
    return camera;
}

}  // namespace clr
