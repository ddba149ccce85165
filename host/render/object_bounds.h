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

// Projects objects for the view of one frame's camera.
class ObjectBounds {
public:
    explicit ObjectBounds(const FrameCamera& camera);

    // A sphere lies inside its axis-aligned box, whose projection bounds the sphere's.
    PixelBounds sphere(const Sphere& sphere) const;
    // A parallelogram projects inside the hull of its corners, which are relative to
    // `corners_origin` ((0, 0, 0): in scene coordinates; FrameGeometry::billboard_origin).
    PixelBounds billboard(const Billboard& billboard, const Vec3& corners_origin) const;

    // No hit on the sphere is nearer than its surface, none on a billboard nearer than its plane.
    double sphere_distance(const Sphere& sphere) const;
    double billboard_distance(const Billboard& billboard, const Vec3& corners_origin) const;

private:
    void add(const Vec3& point, const Vec3& eye, PixelBounds& bounds) const;
    void add_clipped(const Vec3* corners, int count, const Vec3& eye, PixelBounds& bounds) const;
    void widen(PixelBounds& bounds, double x, double y, double depth) const;
    bool box_clearly_in_front(const Vec3& center, double half_size) const;

    Vec3 eye_, forward_, right_, up_;
    Vec3 right_scaled_, up_scaled_;  // right / |right|^2, up / |up|^2: x / depth gives sx
    int width_, height_;
};

}  // namespace clr
