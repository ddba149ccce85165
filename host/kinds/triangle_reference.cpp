// The triangle kind in the double-precision reference renderer (triangle_kind.h), from the
// lecture's formulas: the ray meets the triangle's plane at t = (c0 - o).n / d.n, and the
// point P there has the barycentric coordinates of the orientation test
// (((c_{i+1} - c_i) x (P - c_i)).n / n.n for each edge, counter-clockwise about n). Whether
// the ray passes inside is decided by the sides of the edges as seen along the ray: each
// corner, relative to the ray's origin, becomes a point of the plane across the ray, and each
// edge's side is the exact sign of the 2D orientation of its two points (the same sides: each
// is d.n times its coordinate), zero where it lies within the edges' band of zero, as the
// kernels decide in float and double (kernels/kinds/triangle_sides.cl). Every triangle around a
// vertex or an edge computes the same points and signs, so a ray through a shared vertex or
// edge is inside one of them. Each triangle's own orientation test rounds in its own plane,
// and both neighbours could refuse a point on their edge (a crack).
#include <algorithm>
#include <array>
#include <cmath>

#include "kinds/triangle_kind.h"
#include "reference/geometry.h"
#include "reference/trace_observer.h"
#include "reference/triangle_tree.h"

namespace clr {

using reference::HitKind;
using reference::detail::is_leaving;

namespace {

// A secondary ray leaves a point that rounding puts a little off its triangle's plane; a
// neighbour in that plane could then be met again at a distance of that rounding. Hits
// nearer than this share of the origin's distance from the eye (the reference traces
// relative to the eye: reference/eye_relative.h) are such rounding, as in the kernels
// (kernels/kinds/triangle.cl, whose float share is larger).
constexpr double kSelfGap = 1e-9;

// Two unit vectors across the unit direction d, with across1 x across2 = d (Duff et al.'s
// branchless basis, as the kernels make it).
struct RayAcross {
    Vec3 across1, across2;
};

RayAcross ray_across(const Vec3& d) {
    const double sign = std::copysign(1.0, d.z);
    const double a = -1.0 / (sign + d.z);
    const double b = d.x * d.y * a;
    return {{1.0 + sign * d.x * d.x * a, sign * b, -sign * d.x}, {b, sign + d.y * d.y * a, -d.y}};
}

struct Across {
    double x, y;
};

Across across_ray(const Vec3& corner, const RayAcross& across) {
    return {dot(corner, across.across1), dot(corner, across.across2)};
}

// p.x q.y - p.y q.x with its sign exact: two products rounded each on its own keep their order,
// so a difference that is not zero has the right sign; where it is zero, Kahan's difference of
// products (each product's rounding exactly, by fused multiply-adds) decides. q, p gives exactly
// the negation.
double edge_orientation(const Across& p, const Across& q) {
    const double difference = p.x * q.y - p.y * q.x;
    if (difference != 0) return difference;
    const double product = p.y * q.x;
    return std::fma(p.x, q.y, -product) + std::fma(-p.y, q.x, product);
}

double norm1(const Vec3& v) { return std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z); }

// The band of the edges' orientations (docs/scene-format.md, Meshes, "Edges and the band"):
// 2^-19 M (L + 2^-22 M), M the norm1() of corner 0 from the ray's origin plus L, L the
// longest edge's norm1(), as the kernels take it (kernels/kinds/triangle_sides.cl).
double edge_band(const std::array<Vec3, 3>& c, const reference::Ray& ray) {
    const double longest = std::max({norm1(c[1] - c[0]), norm1(c[2] - c[1]), norm1(c[0] - c[2])});
    const double reach = norm1(c[0] - ray.origin) + longest;
    return std::ldexp(1.0, -19) * reach * (longest + std::ldexp(1.0, -22) * reach);
}

// How the ray passes the triangle's edges: inside, where each edge's orientation across the
// ray (its volume with the ray) is of one sign or within the band of zero (the ray passes
// through that edge) and their sum is beyond the band on that sign (one seen within the band of
// edge on is not met); and whether it is inside by the band alone, one orientation of the
// other sign. Each corner is taken relative to the origin once, the same whichever triangle asks.
struct EdgeSides {
    bool inside = false, by_band = false;
};

EdgeSides edge_sides(const std::array<Vec3, 3>& c, const reference::Ray& ray) {
    const RayAcross across = ray_across(ray.direction);
    const Across a = across_ray(c[0] - ray.origin, across), b = across_ray(c[1] - ray.origin, across),
                 cc = across_ray(c[2] - ray.origin, across);
    const double u = edge_orientation(b, cc), v = edge_orientation(cc, a), w = edge_orientation(a, b);
    const double band = edge_band(c, ray), det = u + v + w;
    EdgeSides sides;
    sides.inside = (u >= -band && v >= -band && w >= -band && det > band) ||
                   (u <= band && v <= band && w <= band && det < -band);
    sides.by_band = det > 0 ? std::min({u, v, w}) < 0 : std::max({u, v, w}) > 0;
    return sides;
}

// Whether p lies within the box of the corners widened by 2^-21 of their largest coordinate (all
// relative to the eye): a hit the band alone admits counts only there, as in the kernels
// (kernels/kinds/triangle_sides.cl, CLR_EDGE_BAND_BOX), inside every box of the reference's tree.
bool within_corner_box(const Vec3& p, const std::array<Vec3, 3>& c) {
    double largest = 0;
    for (const Vec3& corner : c)
        largest = std::max({largest, std::fabs(corner.x), std::fabs(corner.y), std::fabs(corner.z)});
    const double room = std::ldexp(largest, -21);
    for (int axis = 0; axis < 3; ++axis) {
        const double lower = std::min({c[0][axis], c[1][axis], c[2][axis]});
        const double upper = std::max({c[0][axis], c[1][axis], c[2][axis]});
        if (!(p[axis] >= lower - room && p[axis] <= upper + room)) return false;
    }
    return true;
}

reference::detail::TriangleTest test_triangle(const Triangle& triangle, const reference::Ray& ray) {
    reference::detail::TriangleTest test;
    const auto& c = triangle.corners;
    const Vec3 n = cross(c[1] - c[0], c[2] - c[0]);
    const double facing = dot(ray.direction, n);
    if (facing == 0) return test;  // parallel to the plane (or no area)
    test.meets_plane = true;
    test.t = dot(c[0] - ray.origin, n) / facing;
    const Vec3 p = ray.origin + ray.direction * test.t;
    const double area2 = dot(n, n);
    // Each orientation test's value over |n|^2 is the barycentric coordinate of the corner
    // opposite the edge.
    test.weights[0] = dot(cross(c[2] - c[1], p - c[1]), n) / area2;
    test.weights[1] = dot(cross(c[0] - c[2], p - c[2]), n) / area2;
    test.weights[2] = dot(cross(c[1] - c[0], p - c[0]), n) / area2;
    const EdgeSides sides = edge_sides(c, ray);
    test.inside = sides.inside && (!sides.by_band || within_corner_box(p, c));
    const double gap = kSelfGap * (std::fabs(ray.origin.x) + std::fabs(ray.origin.y) + std::fabs(ray.origin.z));
    test.ahead = test.t > gap;
    return test;
}

// How far the plane's point is from the triangle's edges, in barycentric units (relative to
// the triangle's size): inside, the smallest coordinate; outside, the largest deficit.
double edge_margin(const reference::detail::TriangleTest& test) {
    const double least = std::min({test.weights[0], test.weights[1], test.weights[2]});
    return std::abs(least);
}

}  // namespace

HitKind TriangleKind::reference_kind() { return HitKind::Triangle; }

// Every triangle, or those whose boxes the ray reaches in the reference's own index
// (reference/triangle_tree.h): the same nearest hit either way, ties in t going to the lowest
// index as they do when the triangles are tested in order.
void TriangleKind::reference_nearest(const Scene& scene, const reference::Ray& ray, const reference::SurfaceId& leaving,
                                     double& nearest_t, reference::Hit& nearest, reference::TraceObserver* observer) {
    const auto test = [&](int i) {
        if (is_leaving(leaving, HitKind::Triangle, i)) return;
        const reference::detail::TriangleTest tested = test_triangle(scene.triangles[i], ray);
        const bool nearer = tested.t < nearest_t ||
                            (tested.t == nearest_t && nearest.kind == HitKind::Triangle && i < nearest.index);
        const bool accepted = tested.meets_plane && tested.ahead && tested.inside && nearer;
        if (observer) observer->triangle_tested(i, tested, nearest_t, accepted);
        if (!accepted) return;
        nearest_t = tested.t;
        nearest = {HitKind::Triangle, i, tested.t, tested.weights[1], tested.weights[2]};
    };
    if (scene.triangle_tree) {
        scene.triangle_tree->visit(ray, nearest_t, test);
        return;
    }
    for (int i = 0; i < static_cast<int>(scene.triangles.size()); ++i) test(i);
}

double TriangleKind::reference_margin(const Scene& scene, const reference::Ray& ray, double t_max,
                                      const reference::SurfaceId& leaving, std::vector<double>& hit_ts) {
    double margin = reference::kInfinity;
    for (int i = 0; i < static_cast<int>(scene.triangles.size()); ++i) {
        if (is_leaving(leaving, HitKind::Triangle, i)) continue;
        const reference::detail::TriangleTest test = test_triangle(scene.triangles[i], ray);
        if (!test.meets_plane || !test.ahead || test.t >= t_max) continue;
        margin = std::min(margin, edge_margin(test));
        if (test.inside) hit_ts.push_back(test.t);
    }
    return margin;
}

// The corner normals blended by the point's barycentric coordinates where the mesh gives
// them (and they do not cancel), else the geometric normal; turned to face the ray.
Vec3 TriangleKind::reference_normal(const Scene& scene, int index, const Vec3& point, const Vec3& direction) {
    const Triangle& triangle = scene.triangles[index];
    const auto& c = triangle.corners;
    const Vec3 geometric = cross(c[1] - c[0], c[2] - c[0]);
    Vec3 normal = geometric;
    if (triangle.normals >= 0) {
        const double area2 = dot(geometric, geometric);
        const double b1 = dot(cross(c[0] - c[2], point - c[2]), geometric) / area2;
        const double b2 = dot(cross(c[1] - c[0], point - c[0]), geometric) / area2;
        const auto& n = scene.corner_normals[triangle.normals];
        const Vec3 blended = n[0] * (1 - b1 - b2) + n[1] * b1 + n[2] * b2;
        if (dot(blended, blended) > 0) normal = blended;
    }
    normal = normalize(normal);
    return dot(normal, direction) > 0 ? -normal : normal;
}

bool TriangleKind::reference_is_mirror(const Scene& scene, int index) {
    return scene.meshes[scene.triangles[index].mesh].is_mirror;
}

reference::ColourSource TriangleKind::reference_own_color(const Scene& scene, const reference::Hit& hit,
                                                          Color& colour) {
    colour = reference_ambient(scene, hit.index);
    return reference::ColourSource::MeshAmbient;
}

const Color& TriangleKind::reference_ambient(const Scene& scene, int index) {
    return scene.meshes[scene.triangles[index].mesh].ambient;
}

}  // namespace clr
