// Where on the screen an object may appear, for the screen tiles (screen_tiles.h): the
// rectangle of pixels that its projection may cover, from a conservative bound of its shape,
// and the least distance at which a ray from the eye can meet it.
#pragma once

#include <limits>

#include "render/frame_camera.h"
#include "scene/scene.h"

namespace clr {

// The pixel rectangle an object may cover, in (fractional) pixel coordinates of which pixel
// centres are the integers; or the whole screen, when the object reaches the eye; or nothing,
// when no primary ray can meet it (`in_front` false: it lies behind the eye or outside the
// view).
struct PixelBounds {
    double col_min = std::numeric_limits<double>::infinity(), col_max = -col_min;
    double row_min = col_min, row_max = -col_min;
    bool whole_screen = false;
    bool in_front = false;
};

// Projects points and polygons for the view of one frame's camera: the tools each kind's
// screen bounds are made of (host/kinds/: pixel_bounds, least_distance).
class ObjectBounds {
public:
    explicit ObjectBounds(const FrameCamera& camera);

    // The eye in scene coordinates, and the view's axes: forward, and right and up scaled so
    // that a point's dot with them over its depth is its screen coordinate in [-1, 1].
    const Vec3& eye() const { return eye_; }
    const Vec3& forward() const { return forward_; }
    const Vec3& right_scaled() const { return right_scaled_; }
    const Vec3& up_scaled() const { return up_scaled_; }
    // The same axes of unit length, and the screen coordinates (sx, sy) that one unit of
    // x / depth and y / depth along them spans: 1 / |right| and 1 / |up|.
    const Vec3& right_unit() const { return right_unit_; }
    const Vec3& up_unit() const { return up_unit_; }
    double screen_x_per_unit() const { return screen_x_per_unit_; }
    double screen_y_per_unit() const { return screen_y_per_unit_; }

    // Widens `bounds` by the point at camera coordinates x, y (scaled) and depth.
    void widen(PixelBounds& bounds, double x, double y, double depth) const;
    // The pixel column of screen coordinate x / depth, and the pixel row of y / depth: the
    // inverse of the kernels' camera_ray, sx and sy in [-1, 1] across the image. The column
    // never falls as sx grows, nor the row as sy falls, rounding included (each step rounds
    // monotonically): the extreme pixels of several points are those of their extreme
    // screen coordinates.
    double column_of(double sx) const { return (sx + 1) * width_ / 2 - 0.5; }
    double row_of(double sy) const { return (1 - sy) * height_ / 2 - 0.5; }
    // Widens `bounds` by the projection of `point` seen from `eye` (in the point's coordinates).
    void add(const Vec3& point, const Vec3& eye, PixelBounds& bounds) const;
    // Widens `bounds` by the part of convex polygon `corners` that rays can reach, for objects
    // that reach behind the eye plane.
    void add_clipped(const Vec3* corners, int count, const Vec3& eye, PixelBounds& bounds) const;
    // Whether every corner of the box of half size `half_size` around `center` lies clearly in
    // front of the eye.
    bool box_clearly_in_front(const Vec3& center, double half_size) const;
    // Whether bounds made by add() say that the object reaches behind the eye plane: then its
    // corners' projection says nothing, and its bounds are those of its part inside the frustum.
    static bool reaches_behind_eye(const PixelBounds& bounds) { return bounds.whole_screen && bounds.in_front; }

private:
    Vec3 eye_, forward_, right_, up_;
    Vec3 right_scaled_, up_scaled_;  // right / |right|^2, up / |up|^2: x / depth gives sx
    Vec3 right_unit_, up_unit_;
    double screen_x_per_unit_, screen_y_per_unit_;
    int width_, height_;
};

}  // namespace clr
