#include "render/frame_camera.h"

#include <algorithm>
#include <cmath>

#include "render/device_structs.h"
#include "shared/clr_samples.h"

namespace clr {
namespace {

double rounded_to_float(double value) { return static_cast<double>(static_cast<float>(value)); }
Vec3 rounded_to_float(const Vec3& v) { return {rounded_to_float(v.x), rounded_to_float(v.y), rounded_to_float(v.z)}; }

}  // namespace

ClrCamera FrameCamera::device() const {
    ClrCamera camera{};
    // The w components, unused by the positions, carry the clip depths (ClrCamera).
    camera.eye = to_float4(eye, static_cast<float>(clip_near));
    camera.forward = to_float4(forward, static_cast<float>(clip_far));
    camera.right = to_float4(right);
    camera.up = to_float4(up);
    camera.width = width;
    camera.height = height;
    camera.samples = samples;
    camera.frame_seed = frame_seed;
    return camera;
}

FrameCamera make_frame_camera(const Vec3& eye, const Vec3& lookat, const Vec3& up, double fov_degrees, int width,
                              int height, const Vec3& origin) {
    const double kPi = 3.14159265358979323846;
    Vec3 relative_eye = eye - origin;
    Vec3 relative_lookat = lookat - origin;
    // Unit vectors before any cross product: `up` and eye - lookat may have any finite length
    // (normalize() copes), but a cross product of a 1e300-long `up` could overflow.
    Vec3 w = normalize(relative_eye - relative_lookat);  // towards the viewer
    Vec3 u = normalize(cross(normalize(up), w));         // screen right
    Vec3 v = cross(w, u);                                // screen up
    // The field of view spans the larger dimension; pixels are square.
    double tan_half = std::tan(fov_degrees * kPi / 360.0);
    double larger = std::max(width, height);
    double half_width = tan_half * width / larger;
    double half_height = tan_half * height / larger;

    FrameCamera camera;
    camera.origin = origin;
    camera.eye = rounded_to_float(relative_eye);
    camera.forward = rounded_to_float(-w);
    camera.right = rounded_to_float(u * half_width);
    camera.up = rounded_to_float(v * half_height);
    camera.width = width;
    camera.height = height;
    return camera;
}

FrameCamera frame_camera(const Scene& scene, const CameraKey& key, int frame) {
    FrameCamera camera =
        make_frame_camera(key.eye, key.lookat, scene.up, scene.fov_degrees, scene.width, scene.height, key.eye);
    camera.samples = scene.sampling.samples_per_pixel;
    camera.frame_seed = clr_frame_seed(scene.sampling.seed, static_cast<unsigned>(frame));
    camera.clip_near = scene.clip_near;
    camera.clip_far = scene.kept_far();
    return camera;
}

}  // namespace clr
