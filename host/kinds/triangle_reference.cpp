// The triangle kind in the double-precision reference renderer (triangle_kind.h), from the
// lecture's formulas: the ray meets the triangle's plane at t = (c0 - o).n / d.n, and the
// point P there has the barycentric coordinates of the orientation test
// (((c_{i+1} - c_i) x (P - c_i)).n / n.n for each edge, counter-clockwise about n). Whether
// the ray passes inside is decided by the sides of the edges as seen along the ray, the signed
// volumes d.((p - o) x (q - o)) (the same sides: each is d.n times its coordinate), made so that
// the triangle on the other side of a shared edge gets exactly the negated volume: a ray
// through a shared edge is inside one of them. Each triangle's own orientation test rounds
// in its own plane, and both neighbours could refuse a point on their edge (a crack).
#include <algorithm>
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

// Whether corner p comes before corner q in the order that makes an edge's volume the same
// operations in both triangles that share it: by x, then y, then z.
bool corner_before(const Vec3& p, const Vec3& q) {
    return p.x < q.x || (p.x == q.x && (p.y < q.y || (p.y == q.y && p.z < q.z)));
}

// d.((p - o) x (q - o)) for the ray and the edge (p, q), computed as d.((s - o) x (t - s)) from
// the corners in corner_before() order and negated for (q, p): the triangle on the other side
// of the edge makes the same operations and negates them, so its value is exactly the negation.
double edge_volume(const Vec3& p, const Vec3& q, const reference::Ray& ray) {
    const bool negated = corner_before(q, p);
    const Vec3& s = negated ? q : p;
    const Vec3& t = negated ? p : q;
    const double volume = dot(ray.direction, cross(s - ray.origin, t - s));
    return negated ? -volume : volume;
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
    const double u = edge_volume(c[1], c[2], ray), v = edge_volume(c[2], c[0], ray), w = edge_volume(c[0], c[1], ray);
    test.inside = (u >= 0 && v >= 0 && w >= 0) || (u <= 0 && v <= 0 && w <= 0);
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
