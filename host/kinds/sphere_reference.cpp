// The sphere kind in the double-precision reference renderer (sphere_kind.h).
#include <algorithm>
#include <cmath>

#include "kinds/sphere_kind.h"
#include "reference/geometry.h"
#include "reference/trace_observer.h"

namespace clr {

using reference::HitKind;
using reference::detail::is_leaving;
using reference::detail::sphere_hit_t;
using reference::detail::sphere_roots;

namespace {

// A sphere's answer changes where the ray's line grazes it: the distance from the centre to
// the line equals r. That matters only for a sphere the ray can reach: one whose closest
// approach lies ahead (t > 0) or which holds the origin, and which starts before t_max; any
// other sphere is missed by every nearby ray. (An origin lying on a sphere's surface is not
// counted: secondary rays skip the surface they leave, and an eye on a surface is a
// degenerate scene.)
double sphere_margin(const Sphere& sphere, const reference::Ray& ray, double t_max) {
    const Vec3 oc = ray.origin - sphere.center;
    const double r = sphere.radius;
    const double t_closest = -dot(oc, ray.direction);
    const bool holds_origin = dot(oc, oc) < r * r;
    const bool reachable = (t_closest > 0 || holds_origin) && t_closest - r < t_max;
    if (!reachable) return reference::kInfinity;
    const double line_distance = length(oc + ray.direction * t_closest);
    return std::abs(line_distance - r) / r;
}

}  // namespace

HitKind SphereKind::reference_kind() { return HitKind::Sphere; }

void SphereKind::reference_nearest(const Scene& scene, const reference::Ray& ray, const reference::SurfaceId& leaving,
                                   double& nearest_t, reference::Hit& nearest, reference::TraceObserver* observer) {
    for (int i = 0; i < static_cast<int>(scene.spheres.size()); ++i) {
        if (is_leaving(leaving, HitKind::Sphere, i)) continue;
        const double t = sphere_hit_t(scene.spheres[i], ray, nearest_t);
        if (observer) observer->sphere_tested(i, sphere_roots(scene.spheres[i], ray), nearest_t, t);
        if (t < nearest_t) {
            nearest_t = t;
            nearest = {HitKind::Sphere, i, t, 0, 0};
        }
    }
}

double SphereKind::reference_margin(const Scene& scene, const reference::Ray& ray, double t_max,
                                    const reference::SurfaceId& leaving, std::vector<double>& hit_ts) {
    double margin = reference::kInfinity;
    for (int i = 0; i < static_cast<int>(scene.spheres.size()); ++i) {
        if (is_leaving(leaving, HitKind::Sphere, i)) continue;
        margin = std::min(margin, sphere_margin(scene.spheres[i], ray, t_max));
        const double t = sphere_hit_t(scene.spheres[i], ray, t_max);
        if (t < t_max) hit_ts.push_back(t);
    }
    return margin;
}

Vec3 SphereKind::reference_normal(const Scene& scene, int index, const Vec3& point, const Vec3&) {
    const Sphere& sphere = scene.spheres[index];
    return (point - sphere.center) / sphere.radius;
}

bool SphereKind::reference_is_mirror(const Scene& scene, int index) { return scene.spheres[index].is_mirror; }

reference::ColourSource SphereKind::reference_own_color(const Scene& scene, const reference::Hit& hit, Color& colour) {
    colour = scene.spheres[hit.index].ambient;
    return reference::ColourSource::SphereAmbient;
}

const Color& SphereKind::reference_ambient(const Scene& scene, int index) { return scene.spheres[index].ambient; }

}  // namespace clr
