#include "reference/triangle_tree.h"

#include <algorithm>
#include <cmath>

namespace clr::reference {

namespace {

constexpr std::uint32_t kLeafSize = 4;
// Deep enough for any tree of median splits over at most 2^24 triangles (the scene's limit),
// and within the traversal's stack of 128 (two entries per level).
constexpr int kMaxDepth = 60;

}  // namespace

TriangleTree::TriangleTree(const std::vector<Triangle>& triangles) {
    if (triangles.empty()) return;
    std::vector<Vec3> centres(triangles.size());
    items_.resize(triangles.size());
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const auto& c = triangles[i].corners;
        centres[i] = (c[0] + c[1] + c[2]) / 3.0;
        items_[i] = static_cast<std::uint32_t>(i);
    }
    nodes_.reserve(2 * triangles.size() / kLeafSize + 2);
    nodes_.emplace_back();
    build(0, 0, static_cast<std::uint32_t>(items_.size()), centres, triangles, 0);
}

// The node's box around its triangles, widened by a millionth of its size plus a tiny
// absolute amount: rounding in the slab test below is some 1e-16 of the distances, so no ray
// that meets a triangle can miss its box. Then a split at the median of the centres along
// their widest axis.
void TriangleTree::build(std::uint32_t node, std::uint32_t begin, std::uint32_t end, const std::vector<Vec3>& centres,
                         const std::vector<Triangle>& triangles, int depth) {
    Vec3 lower{INFINITY, INFINITY, INFINITY}, upper = -lower;
    Vec3 centre_lower = lower, centre_upper = upper;
    for (std::uint32_t k = begin; k < end; ++k) {
        for (const Vec3& corner : triangles[items_[k]].corners) {
            lower = {std::min(lower.x, corner.x), std::min(lower.y, corner.y), std::min(lower.z, corner.z)};
            upper = {std::max(upper.x, corner.x), std::max(upper.y, corner.y), std::max(upper.z, corner.z)};
        }
        const Vec3& c = centres[items_[k]];
        centre_lower = {std::min(centre_lower.x, c.x), std::min(centre_lower.y, c.y), std::min(centre_lower.z, c.z)};
        centre_upper = {std::max(centre_upper.x, c.x), std::max(centre_upper.y, c.y), std::max(centre_upper.z, c.z)};
    }
    const Vec3 size = upper - lower;
    const double pad = 1e-6 * std::max({size.x, size.y, size.z, std::fabs(lower.x), std::fabs(lower.y),
                                        std::fabs(lower.z), std::fabs(upper.x), std::fabs(upper.y), std::fabs(upper.z)}) +
                       1e-300;
    nodes_[node].lower = lower - Vec3{pad, pad, pad};
    nodes_[node].upper = upper + Vec3{pad, pad, pad};
    const Vec3 spread = centre_upper - centre_lower;
    const int axis = spread.x >= spread.y && spread.x >= spread.z ? 0 : (spread.y >= spread.z ? 1 : 2);
    if (end - begin <= kLeafSize || depth >= kMaxDepth || spread[axis] == 0) {
        nodes_[node].first = begin;
        nodes_[node].count = end - begin;
        return;
    }
    const std::uint32_t middle = begin + (end - begin) / 2;
    std::nth_element(items_.begin() + begin, items_.begin() + middle, items_.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) { return centres[a][axis] < centres[b][axis]; });
    const std::uint32_t left = static_cast<std::uint32_t>(nodes_.size());
    nodes_[node].first = left;
    nodes_[node].count = 0;
    nodes_.emplace_back();
    nodes_.emplace_back();
    build(left, begin, middle, centres, triangles, depth + 1);
    build(left + 1, middle, end, centres, triangles, depth + 1);
}

// The slab test on (0, t_max]. An axis the ray runs parallel to is a test of the origin
// alone (no 0 * infinity).
bool TriangleTree::reaches(const Node& node, const Ray& ray, double t_max) {
    double enter = 0, leave = t_max;
    for (int axis = 0; axis < 3; ++axis) {
        const double o = ray.origin[axis], d = ray.direction[axis];
        const double lo = node.lower[axis], hi = node.upper[axis];
        if (d == 0) {
            if (o < lo || o > hi) return false;
            continue;
        }
        double t0 = (lo - o) / d, t1 = (hi - o) / d;
        if (t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0);
        leave = std::min(leave, t1);
        if (enter > leave) return false;
    }
    return true;
}

}  // namespace clr::reference
