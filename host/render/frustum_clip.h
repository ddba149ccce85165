// The part of a polygon that primary rays can reach, for the screen tiles of objects that
// reach behind the eye plane. Such an object's projection is unbounded, and it used to be
// listed in every tile; but rays leave the eye only inside the view frustum, so only the part
// of the object inside the frustum matters, and that part projects inside the screen.
// In a forest flown through at tree height, a hundred trees beside and behind the camera
// cross the eye plane in every frame; listed everywhere, they were tested by every pixel
// (docs/benchmarks.md, Impostors and the forest).
#pragma once

#include <vector>

namespace clr {

// A point in the camera's frame, relative to the eye: z its depth along the view direction,
// x and y scaled so that the screen's edges lie at x = +-z and y = +-z.
struct ViewPoint {
    double x = 0, y = 0, z = 0;
};

// The view frustum that clipping keeps, a little wider than the screen: every side moved out
// by `margin_x` (in units of x / z) or `margin_y`, and its apex moved back behind the eye by
// `apex_back` (in units of z), so that it holds a neighbourhood of the eye as well.
struct ClipFrustum {
    double margin_x = 0, margin_y = 0, apex_back = 0;
};

// The convex polygon `polygon` (its vertices in order) clipped to `frustum`: empty when no
// part of it lies inside, otherwise a convex polygon whose points all lie inside.
std::vector<ViewPoint> clip_to_frustum(const std::vector<ViewPoint>& polygon, const ClipFrustum& frustum);

}  // namespace clr
