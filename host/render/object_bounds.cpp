#include "render/object_bounds.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "render/frustum_clip.h"

namespace clr {
namespace {

// Clipping keeps what lies within this many pixels outside the screen: far more than the
// kernels' float rays can stray from the exact ones.
constexpr double kClipMarginPixels = 4;
// A polygon that passes within this fraction of its distance from the eye counts as touching
// it (float positions are exact to about 6e-8 of their distance).
constexpr double kNearEyeFraction = 1e-5;

}  // namespace

ObjectBounds::ObjectBounds(const FrameCamera& camera)
    : eye_(camera.eye_in_scene()), forward_(camera.forward), right_(camera.right), up_(camera.up),
      right_scaled_(camera.right / dot(camera.right, camera.right)), up_scaled_(camera.up / dot(camera.up, camera.up)),
      right_unit_(normalize(camera.right)), up_unit_(normalize(camera.up)),
      screen_x_per_unit_(1 / length(camera.right)), screen_y_per_unit_(1 / length(camera.up)),
      width_(camera.width), height_(camera.height) {}

// Widens `bounds` by the point at camera coordinates x, y (scaled: the screen's edges at
// x / depth = +-1) and depth.
void ObjectBounds::widen(PixelBounds& bounds, double x, double y, double depth) const {
    const double col = column_of(x / depth);
    const double row = row_of(y / depth);
    bounds.col_min = std::min(bounds.col_min, col);
    bounds.col_max = std::max(bounds.col_max, col);
    bounds.row_min = std::min(bounds.row_min, row);
    bounds.row_max = std::max(bounds.row_max, row);
}

// Widens `bounds` by the projection of `point`, seen from `eye` (in the point's coordinates). A
// point less than a small fraction of the scene's distance in front of the eye counts as behind
// it. An object whose points are all clearly behind the eye plane (by more than float rounding
// could move them) is never met: every primary ray travels forwards, so every hit has a
// positive depth, and so would any point of the object's convex hull that a ray could reach.
void ObjectBounds::add(const Vec3& point, const Vec3& eye, PixelBounds& bounds) const {
    Vec3 rel = point - eye;
    double depth = dot(rel, forward_);
    if (!(depth < -1e-6 * length(rel))) bounds.in_front = true;
    if (!(depth > 1e-7 * length(rel))) {
        bounds.whole_screen = true;
        return;
    }
    widen(bounds, dot(rel, right_scaled_), dot(rel, up_scaled_), depth);
}

// Widens `bounds` by the projection of the part of convex polygon `corners` that rays can
// reach: the part inside the view frustum, widened by kClipMarginPixels on every side and with
// its apex moved back by a small fraction of the polygon's distance, more than float rounding
// of the kernels' positions could move it. A polygon that comes that close to the eye covers
// the whole screen. For objects that reach behind the eye plane.
void ObjectBounds::add_clipped(const Vec3* corners, int count, const Vec3& eye, PixelBounds& bounds) const {
    std::vector<ViewPoint> polygon;
    double distance = 0;
    for (int i = 0; i < count; ++i) {
        Vec3 rel = corners[i] - eye;
        polygon.push_back({dot(rel, right_scaled_), dot(rel, up_scaled_), dot(rel, forward_)});
        distance = std::max(distance, length(rel));
    }
    const ClipFrustum frustum{2.0 * kClipMarginPixels / width_, 2.0 * kClipMarginPixels / height_,
                              kNearEyeFraction * distance};
    for (const ViewPoint& p : clip_to_frustum(polygon, frustum)) {
        bounds.in_front = true;
        if (!(p.z > frustum.apex_back)) {
            bounds.whole_screen = true;
            return;
        }
        widen(bounds, p.x, p.y, p.z);
    }
}

// Whether every corner of the axis-aligned box of half size `half_size` around `center` lies
// clearly in front of the eye: deeper than add() asks, with room for rounding to spare.
bool ObjectBounds::box_clearly_in_front(const Vec3& center, double half_size) const {
    const Vec3 rel = center - eye_;
    const double least_depth =
        dot(rel, forward_) - half_size * (std::fabs(forward_.x) + std::fabs(forward_.y) + std::fabs(forward_.z));
    return least_depth > 1e-6 * (length(rel) + half_size * std::sqrt(3.0));
}

}  // namespace clr
