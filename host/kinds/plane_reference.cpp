// The plane kind in the double-precision reference renderer (plane_kind.h).
#include <algorithm>
#include <cmath>

#include "kinds/plane_kind.h"
#include "reference/geometry.h"
#include "reference/trace_observer.h"

namespace clr {

using reference::HitKind;
using reference::detail::is_leaving;

namespace {

// The lecture's ray-plane intersection: t = ((P0 - o).n) / (d.n), accepted for 0 < t < t_max;
// a ray parallel to the plane misses it.
double plane_hit_t(const Plane& plane, const reference::Ray& ray, double t_max) {
    const double along = dot(ray.direction, plane.normal);
    if (along == 0) return reference::kInfinity;
    const double t = dot(plane.point - ray.origin, plane.normal) / along;
    return t > 0 && t < t_max ? t : reference::kInfinity;
}

}  // namespace

HitKind PlaneKind::reference_kind() { return HitKind::Plane; }

void PlaneKind::reference_nearest(const Scene& scene, const reference::Ray& ray, const reference::SurfaceId& leaving,
                                  double& nearest_t, reference::Hit& nearest, reference::TraceObserver* observer) {
    for (int i = 0; i < static_cast<int>(scene.planes.size()); ++i) {
        if (is_leaving(leaving, HitKind::Plane, i)) continue;
        const double t = plane_hit_t(scene.planes[i], ray, nearest_t);
        if (observer) observer->plane_tested(i, t);
        if (t < nearest_t) {
            nearest_t = t;
            nearest = {HitKind::Plane, i, t, 0, 0};
        }
    }
}

// A plane's answer changes where the ray turns parallel to it (the horizon): |d.n|, the sine
// of the angle between the ray and the plane.
double PlaneKind::reference_margin(const Scene& scene, const reference::Ray& ray, double t_max,
                                   const reference::SurfaceId& leaving, std::vector<double>& hit_ts) {
    double margin = reference::kInfinity;
    for (int i = 0; i < static_cast<int>(scene.planes.size()); ++i) {
        if (is_leaving(leaving, HitKind::Plane, i)) continue;
        margin = std::min(margin, std::abs(dot(ray.direction, scene.planes[i].normal)));
        const double t = plane_hit_t(scene.planes[i], ray, t_max);
        if (t < t_max) hit_ts.push_back(t);
    }
    return margin;
}

Vec3 PlaneKind::reference_normal(const Scene& scene, int index, const Vec3&, const Vec3& direction) {
    const Vec3& normal = scene.planes[index].normal;
    return dot(normal, direction) > 0 ? -normal : normal;
}

bool PlaneKind::reference_is_mirror(const Scene&, int) { return false; }

reference::ColourSource PlaneKind::reference_own_color(const Scene& scene, const reference::Hit& hit, Color& colour) {
    colour = scene.planes[hit.index].ambient;
    return reference::ColourSource::PlaneAmbient;
}

const Color& PlaneKind::reference_ambient(const Scene& scene, int index) { return scene.planes[index].ambient; }

}  // namespace clr
