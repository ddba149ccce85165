// The double-precision host reference: an independent implementation of every kernel stage
// (camera rays, nearest-hit intersection, shading), written from the lecture's formulas and
// the conventions of docs/scene-format.md, not from the kernels. Tests compare each kernel with it; `--reference`
// renders with it.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

#include "core/pixel_rect.h"
#include "scene/scene.h"

namespace clr::reference {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Ray {
    Vec3 origin;
    Vec3 direction;  // unit length
    // The part of a primary ray that the camera's clip depths keep (docs/scene-format.md, Near
    // and far clipping): trace() looks for its first hit with t_start < t < t_end only.
    double t_start = 0;
    double t_end = kInfinity;
};

// The camera of one frame (docs/scene-format.md, Conventions: Camera).
struct CameraFrame {
    Vec3 eye;
    Vec3 u, v, w;        // orthonormal: u screen right, v screen up, w towards the viewer
    double half_width;   // half the image plane's extent along u, at distance 1
    double half_height;  // half the extent along v
    int width = 0, height = 0;
    double clip_near = 0;          // primary rays see depths along -w from clip_near ...
    double clip_far = kInfinity;   // ... to clip_far (Scene::clip_near, clip_far)
};

CameraFrame make_camera(const Vec3& eye, const Vec3& lookat, const Vec3& up, double fov_degrees, int width,
                        int height);
// The camera at `key` with the scene's up vector, field of view and image size.
CameraFrame camera_of(const Scene& scene, const CameraKey& key);

// The ray from the eye through the centre of pixel (col, row); row 0 is the top row.
Ray primary_ray(const CameraFrame& camera, int col, int row);

// The witness point of image point (col + ox, row + oy) minus the eye: the image plane sits at
// distance 1 along -w (the lecture's "Witness points", D = 1). primary_ray_through()'s direction
// is this, made unit.
Vec3 witness_direction(const CameraFrame& camera, int col, int row, double ox, double oy);

// The ray through point (col + ox, row + oy) of the image, ox and oy in [0, 1) inside pixel
// (col, row): a sample of the pixel (anti-aliasing).
Ray primary_ray_through(const CameraFrame& camera, int col, int row, double ox, double oy);

class TraceObserver;  // reference/trace_observer.h

enum class HitKind { None, Sphere, Billboard, Triangle, Plane };

struct Hit {
    HitKind kind = HitKind::None;
    int index = -1;
    double t = kInfinity;  // distance along the unit direction
    // Billboard coordinates of the hit, P = UL + a(UR-UL) + b(LL-UL); on a triangle, its
    // barycentric coordinates of corners 1 and 2, P = c0 + a(c1-c0) + b(c2-c0).
    double a = 0, b = 0;
};

// The surface a secondary ray leaves, which it must not hit again.
struct SurfaceId {
    HitKind kind = HitKind::None;
    int index = -1;
    // A second surface of the same kind left too: for a triangle hit settled onto another
    // (reference/shade.cpp, settled()), the one shaded; -1: none.
    int also = -1;
};

// intersect(), decision_margin() and trace() see spheres, billboards and mesh triangles, not
// impostors: impostors face a camera, so a scene with impostors must be placed for that camera
// first (with_impostors_placed() in reference/impostors.h). render() does that itself.

// Nearest surface with 0 < t < t_max, skipping `leaving`. Billboard texels whose alpha is
// below 255 let the ray through.
Hit intersect(const Scene& scene, const Ray& ray, double t_max = kInfinity, SurfaceId leaving = {});
// The same search, telling `observer` (when not null) each surface tested (trace_observer.h).
Hit intersect(const Scene& scene, const Ray& ray, double t_max, SurfaceId leaving, TraceObserver* observer);
// The nearest hit of a primary ray within its kept part (t_start, t_end): the search starts at
// origin + t_start direction; the hit's t is from the origin again.
Hit intersect_in_view(const Scene& scene, const Ray& ray, TraceObserver* observer = nullptr);

// How close `ray` passes to a place where intersect()'s answer changes: a sphere's
// silhouette, a billboard's edge, the edge of a texel, or two surfaces at nearly the same
// depth. Relative measure (distances divided by the sphere radius, by the billboard's unit
// coordinates, by the depth); tests allow float kernels to disagree only where this is small.
double decision_margin(const Scene& scene, const Ray& ray);

// The colour seen along a primary ray: flat or sun-lit surfaces, shadows, mirrors up to the
// scene's MaxDepth, background (docs/scene-format.md, Conventions: Lighting and shadows;
// docs/scene-format.md, Conventions: Mirrors). Unclamped.
Color trace(const Scene& scene, const Ray& ray);
// The same colour, telling `observer` (when not null) each step (trace_observer.h).
Color trace(const Scene& scene, const Ray& ray, TraceObserver* observer);

// Display byte for a colour channel: round(clamp(c, 0, 1) * 255).
std::uint8_t to_byte(double channel);

// The unclamped colour of pixel (col, row) of frame `frame`: the mean of its samples, exactly
// as render() computes it, telling `observer` (when not null) each step. Like trace(), it does
// not see impostors: place them first; and it traces `scene` where it lies:
// render() traces relative_to_eye()'s scene and camera (reference/eye_relative.h), so pass
// those for render()'s numbers.
Color pixel_colour(const Scene& scene, const CameraFrame& camera, int frame, int col, int row,
                   TraceObserver* observer = nullptr);

// Renders one frame: RGBA bytes, alpha 255, rows from the top. Each pixel is the mean of
// scene.sampling.samples_per_pixel samples placed as kernels/shared/clr_samples.h says for
// this frame index (one sample: the pixel's centre). The scene is traced relative to the
// camera's eye (reference/eye_relative.h), with impostors placed for `camera` first.
// `between_rows` runs before each row; it throws to abandon the frame (a stop request).
// With `crop`, only those pixels, into an image of the crop's size (docs/command-line.md, Crop).
Image render(const Scene& scene, const CameraFrame& camera, int frame = 0,
             const std::function<void()>& between_rows = {}, const std::optional<PixelRect>& crop = std::nullopt);

// Renders one frame (or its `crop`) as render() does, and also its linear colours (Image::linear): per pixel
// the mean of its samples' colours as float, unclamped, and the fraction of its samples whose
// primary ray hits an object (docs/command-line.md, HDR and alpha outputs).
Image render_linear(const Scene& scene, const CameraFrame& camera, int frame = 0,
                    const std::function<void()>& between_rows = {},
                    const std::optional<PixelRect>& crop = std::nullopt);

}  // namespace clr::reference
