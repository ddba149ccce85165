// Reference camera: the orthonormal basis and the witness point of each pixel
// (docs/scene-format.md, Conventions: Camera; the lecture's "Building coordinates system" and
// "Witness points").
#include <cmath>

#include "reference/reference.h"

namespace clr::reference {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

CameraFrame make_camera(const Vec3& eye, const Vec3& lookat, const Vec3& up, double fov_degrees, int width,
                        int height) {
    CameraFrame camera;
    camera.eye = eye;
    // Directions of any finite length (normalize() scales before squaring); `up` is made
    // unit before the cross product, which could overflow for a 1e300-long `up`.
    camera.w = normalize(eye - lookat);                    // points back, towards the viewer
    camera.u = normalize(cross(normalize(up), camera.w));  // screen right
    camera.v = cross(camera.w, camera.u);       // screen up; unit because w and u are orthonormal
    camera.width = width;
    camera.height = height;

    // The image plane sits at distance 1, so tan(fov/2) is half its extent across the larger
    // image dimension; the smaller one is scaled down so that pixels stay square.
    const double half_extent = std::tan(fov_degrees * kPi / 360.0);
    if (width >= height) {
        camera.half_width = half_extent;
        camera.half_height = half_extent * height / width;
    } else {
        camera.half_height = half_extent;
        camera.half_width = half_extent * width / height;
    }
    return camera;
}

CameraFrame camera_of(const Scene& scene, const CameraKey& key) {
    CameraFrame camera = make_camera(key.eye, key.lookat, scene.up, scene.fov_degrees, scene.width, scene.height);
    camera.clip_near = scene.clip_near;
    camera.clip_far = scene.kept_far();
    return camera;
}

Ray primary_ray(const CameraFrame& camera, int col, int row) { return primary_ray_through(camera, col, row, 0.5, 0.5); }

Vec3 witness_direction(const CameraFrame& camera, int col, int row, double ox, double oy) {
    // Image points (col + ox, row + oy) mapped to [-1, 1], row 0 at the top (+v).
    const double x = 2.0 * (col + ox) / camera.width - 1.0;
    const double y = 1.0 - 2.0 * (row + oy) / camera.height;
    return -camera.w + camera.u * (x * camera.half_width) + camera.v * (y * camera.half_height);
}

Ray primary_ray_through(const CameraFrame& camera, int col, int row, double ox, double oy) {
    Ray ray{camera.eye, normalize(witness_direction(camera, col, row, ox, oy))};
    // A point at distance t along the ray lies at depth t (d . -w) along the view direction.
    if (camera.clip_near > 0 || camera.clip_far < kInfinity) {
        const double depth_per_t = -dot(ray.direction, camera.w);
        ray.t_start = camera.clip_near / depth_per_t;
        ray.t_end = camera.clip_far / depth_per_t;
    }
    return ray;
}

}  // namespace clr::reference
