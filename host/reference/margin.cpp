// How far a ray is from changing the reference's answer. Float kernels see slightly
// different rays; where this margin is tiny they may legitimately pick another surface or
// texel, and tests excuse exactly those pixels.
#include <algorithm>
#include <cmath>
#include <vector>

#include "reference/geometry.h"

namespace clr::reference {

using detail::is_leaving;
using detail::is_textured;

namespace {

// A sphere's answer changes where the ray's line grazes it: the distance from the centre to
// the line equals r. That matters only for a sphere the ray can reach: one whose closest
// approach lies ahead (t > 0) or which holds the origin, and which starts before t_max; any
// other sphere is missed by every nearby ray. (An origin lying on a sphere's surface is not
// counted: secondary rays skip the surface they leave, and an eye on a surface is a
// degenerate scene.)
double sphere_margin(const Sphere& sphere, const Ray& ray, double t_max) {
    const Vec3 oc = ray.origin - sphere.center;
    const double r = sphere.radius;
    const double t_closest = -dot(oc, ray.direction);
    const bool holds_origin = dot(oc, oc) < r * r;
    const bool reachable = (t_closest > 0 || holds_origin) && t_closest - r < t_max;
    if (!reachable) return kInfinity;
    const double line_distance = length(oc + ray.direction * t_closest);
    return std::abs(line_distance - r) / r;
}

// Euclidean distance in (a, b) from the point to the boundary of the unit square, inside or
// outside: (a, b) measures in units of the billboard's edges, so this is relative to its size.
double square_edge_distance(double a, double b) {
    const double outside_a = std::max({-a, 0.0, a - 1});
    const double outside_b = std::max({-b, 0.0, b - 1});
    if (outside_a > 0 || outside_b > 0) return std::hypot(outside_a, outside_b);
    return std::min({a, 1 - a, b, 1 - b});
}

// Distance in (a, b) to the nearest line between texels: lines sit at a = k/W and b = k/H.
double texel_edge_distance(const Image& image, double a, double b) {
    const double texels_a = a * image.width;
    const double texels_b = b * image.height;
    return std::min(std::abs(texels_a - std::round(texels_a)) / image.width,
                    std::abs(texels_b - std::round(texels_b)) / image.height);
}

// The depth order of the two nearest hits flips when their t differ by little, relative to t.
double depth_margin(std::vector<double> hit_ts) {
    if (hit_ts.size() < 2) return kInfinity;
    std::partial_sort(hit_ts.begin(), hit_ts.begin() + 2, hit_ts.end());
    return (hit_ts[1] - hit_ts[0]) / hit_ts[0];
}

}  // namespace

namespace detail {

double ray_margin(const Scene& scene, const Ray& ray, double t_max, SurfaceId leaving, bool depth_order_matters) {
    double margin = kInfinity;
    std::vector<double> hit_ts;  // accepted hits in (0, t_max)
    for (int i = 0; i < static_cast<int>(scene.spheres.size()); ++i) {
        if (is_leaving(leaving, HitKind::Sphere, i)) continue;
        margin = std::min(margin, sphere_margin(scene.spheres[i], ray, t_max));
        const double t = sphere_hit_t(scene.spheres[i], ray, t_max);
        if (t < t_max) hit_ts.push_back(t);
    }
    for (int i = 0; i < static_cast<int>(scene.billboards.size()); ++i) {
        if (is_leaving(leaving, HitKind::Billboard, i)) continue;
        const Billboard& billboard = scene.billboards[i];
        const PlaneHit plane = billboard_plane_hit(billboard, ray);
        if (!plane.meets || plane.t <= 0 || plane.t >= t_max) continue;
        margin = std::min(margin, square_edge_distance(plane.a, plane.b));
        if (!inside_unit_square(plane.a, plane.b)) continue;
        if (is_textured(billboard)) {
            const Image& image = *billboard.image;
            margin = std::min(margin, texel_edge_distance(image, plane.a, plane.b));
            if (!texel_is_opaque(image, texel_at(image, plane.a, plane.b))) continue;
        }
        hit_ts.push_back(plane.t);
    }
    if (depth_order_matters) margin = std::min(margin, depth_margin(std::move(hit_ts)));
    return margin;
}

}  // namespace detail

// The margin of every ray trace() follows for this pixel: the primary ray, each reflected
// ray, and the shadow ray of a lit surface, plus how squarely each mirror is met (d.n near 0
// is where front turns into back). For a ray that hits a plain surface in flat mode this is
// the primary ray's margin alone.
double decision_margin(const Scene& scene, const Ray& ray) {
    double margin = kInfinity;
    Ray current = ray;
    SurfaceId leaving;
    for (int reflections = 0;; ++reflections) {
        margin = std::min(margin, detail::ray_margin(scene, current, kInfinity, leaving, true));
        const Hit hit = intersect(scene, current, kInfinity, leaving);
        if (hit.kind == HitKind::None) return margin;
        const detail::SurfacePoint surface = detail::surface_at(scene, current, hit);

        if (surface.is_mirror) {
            margin = std::min(margin, std::abs(dot(current.direction, surface.normal)));
            if (!detail::sees_front(current, surface) || reflections >= scene.max_depth) return margin;
            current = detail::reflect(current, surface);
            leaving = surface.id;
            continue;
        }
        if (detail::is_lit(hit.kind) && scene.lit()) {
            const auto sun = detail::sun_direction(scene, surface.point);
            if (sun.exists && dot(surface.normal, sun.l) > 0) {
                const Ray shadow_ray{surface.point, sun.l};
                margin = std::min(margin, detail::ray_margin(scene, shadow_ray, sun.distance, surface.id, false));
            }
        }
        return margin;
    }
}

}  // namespace clr::reference
