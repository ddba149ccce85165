// How far a ray is from changing the reference's answer. Float kernels see slightly
// different rays; where this margin is tiny they may legitimately pick another surface or
// texel, and tests excuse exactly those pixels.
#include <algorithm>
#include <cmath>
#include <vector>

#include "kinds/kinds.h"
#include "reference/geometry.h"

namespace clr::reference {

namespace {

// The depth order of the two nearest hits flips when their t differ by little, relative to t.
double depth_margin(std::vector<double> hit_ts) {
    if (hit_ts.size() < 2) return kInfinity;
    std::partial_sort(hit_ts.begin(), hit_ts.begin() + 2, hit_ts.end());
    return (hit_ts[1] - hit_ts[0]) / hit_ts[0];
}

}  // namespace

namespace detail {
double ray_margin(const Scene& scene, const Ray& ray, double t_max, SurfaceId leaving, bool depth_order_matters);
}  // namespace detail

namespace {

// The primary ray's margin over the part of it that the clip depths keep.
double primary_margin(const Scene& scene, const Ray& ray) {
    if (ray.t_start == 0) return detail::ray_margin(scene, ray, ray.t_end, {}, true);
    const Ray kept{ray.origin + ray.direction * ray.t_start, ray.direction};
    return detail::ray_margin(scene, kept, ray.t_end - ray.t_start, {}, true);
}

// A hit of the whole ray close to the near or the far clip depth is kept or cut by rounding:
// the relative distance of every hit from the two ends of the kept part.
double clip_margin(const Scene& scene, const Ray& ray) {
    std::vector<double> hit_ts;
    for_each_kind([&](auto kind) { decltype(kind)::reference_margin(scene, ray, kInfinity, {}, hit_ts); });
    double margin = kInfinity;
    for (double t : hit_ts) {
        margin = std::min(margin, std::abs(t - ray.t_start) / t);
        if (ray.t_end < kInfinity) margin = std::min(margin, std::abs(t - ray.t_end) / t);
    }
    return margin;
}

}  // namespace

namespace detail {

double ray_margin(const Scene& scene, const Ray& ray, double t_max, SurfaceId leaving, bool depth_order_matters) {
    double margin = kInfinity;
    std::vector<double> hit_ts;  // accepted hits in (0, t_max)
    for_each_kind([&](auto kind) {
        margin = std::min(margin, decltype(kind)::reference_margin(scene, ray, t_max, leaving, hit_ts));
    });
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
    if (ray.t_start > 0 || ray.t_end < kInfinity) margin = clip_margin(scene, ray);
    for (int reflections = 0;; ++reflections) {
        margin = std::min(margin, reflections == 0 ? primary_margin(scene, current)
                                                   : detail::ray_margin(scene, current, kInfinity, leaving, true));
        const Hit hit = reflections == 0 ? intersect_in_view(scene, current) : intersect(scene, current, kInfinity, leaving);
        if (hit.kind == HitKind::None) return margin;
        const detail::SurfacePoint surface = detail::surface_at(scene, current, hit);

        if (surface.is_mirror) {
            margin = std::min(margin, std::abs(dot(current.direction, surface.normal)));
            if (!detail::sees_front(current, surface) || reflections >= scene.max_depth) return margin;
            current = detail::reflect(current, surface);
            leaving = surface.id;
            continue;
        }
        if (detail::is_lit(hit.kind) && scene.lit_by_lights()) {
            // Each light's shadow ray; where a highlight is cut off at n.l = 0, that too.
            const Material& material = detail::material_of(scene, hit);
            for (const PointLight& light : scene.lights) {
                const Vec3 to_light = light.position - surface.point;
                const double distance = length(to_light);
                if (!(distance > 0)) continue;
                const Vec3 l = to_light / distance;
                const double cosine = dot(surface.normal, l);
                if (!(material.specular == Color{0, 0, 0})) margin = std::min(margin, std::abs(cosine));
                if (cosine > 0)
                    margin = std::min(margin, detail::ray_margin(scene, {surface.point, l}, distance, surface.id, false));
            }
            if (material.mirror == Color{0, 0, 0} || reflections >= scene.max_depth) return margin;
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
