// An axis-aligned box in double, grown point by point: an object's bounds (host/kinds/) and a
// BVH node's (render/bvh). Empty until grown: lower +inf, upper -inf.
#pragma once

#include <algorithm>
#include <limits>

#include "core/vec3.h"

namespace clr {

struct Box3 {
    Vec3 lower{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
               std::numeric_limits<double>::infinity()};
    Vec3 upper = -lower;

    void grow(const Vec3& p) {
        lower = {std::min(lower.x, p.x), std::min(lower.y, p.y), std::min(lower.z, p.z)};
        upper = {std::max(upper.x, p.x), std::max(upper.y, p.y), std::max(upper.z, p.z)};
    }
    void grow(const Box3& b) {
        if (b.lower.x > b.upper.x) return;  // empty (an unused bin): growing by its infinities would be wrong
        grow(b.lower);
        grow(b.upper);
    }
    // The squared distance from `p` to the box's nearest point (0 inside it).
    double squared_distance_to(const Vec3& p) const {
        const Vec3 nearest{std::clamp(p.x, lower.x, upper.x), std::clamp(p.y, lower.y, upper.y),
                           std::clamp(p.z, lower.z, upper.z)};
        const Vec3 away = p - nearest;
        return dot(away, away);
    }
    double area() const {
        if (lower.x > upper.x) return 0;
        Vec3 d = upper - lower;
        return 2 * (d.x * d.y + d.y * d.z + d.z * d.x);
    }
};

}  // namespace clr
