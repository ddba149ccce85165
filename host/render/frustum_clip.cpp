#include "render/frustum_clip.h"

namespace clr {
namespace {

// A side of the frustum as the half-space where side(p) = a * x + b * y + c * (z + apex_back)
// is at least zero.
struct Side {
    double a, b, c, apex_back;
    double operator()(const ViewPoint& p) const { return a * p.x + b * p.y + c * (p.z + apex_back); }
};

// One step of Sutherland-Hodgman: the part of a convex polygon on the inner side of `side`.
std::vector<ViewPoint> clip_to_side(const std::vector<ViewPoint>& polygon, const Side& side) {
    std::vector<ViewPoint> kept;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const ViewPoint& from = polygon[i];
        const ViewPoint& to = polygon[(i + 1) % polygon.size()];
        const double from_side = side(from), to_side = side(to);
        if (from_side >= 0) kept.push_back(from);
        if ((from_side >= 0) != (to_side >= 0)) {
            const double s = from_side / (from_side - to_side);
            kept.push_back({from.x + s * (to.x - from.x), from.y + s * (to.y - from.y), from.z + s * (to.z - from.z)});
        }
    }
    return kept;
}

}  // namespace

std::vector<ViewPoint> clip_to_frustum(const std::vector<ViewPoint>& polygon, const ClipFrustum& frustum) {
    const double wide_x = 1 + frustum.margin_x, wide_y = 1 + frustum.margin_y;
    // x <= wide_x (z + apex_back), -x <= ..., and the same for y: together they also keep
    // z >= -apex_back, so nothing clearly behind the eye survives.
    const Side sides[] = {{-1, 0, wide_x, frustum.apex_back},
                          {1, 0, wide_x, frustum.apex_back},
                          {0, -1, wide_y, frustum.apex_back},
                          {0, 1, wide_y, frustum.apex_back}};
    std::vector<ViewPoint> clipped = polygon;
    for (const Side& side : sides) {
        if (clipped.empty()) break;
        clipped = clip_to_side(clipped, side);
    }
    return clipped;
}

}  // namespace clr
