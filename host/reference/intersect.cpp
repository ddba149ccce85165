// Reference nearest-hit search over every kind of object (host/kinds/kinds.h).
#include "kinds/kinds.h"
#include "reference/geometry.h"
#include "reference/trace_observer.h"

namespace clr::reference {

// Kind by kind, object by object (each kind's reference_nearest()): ties in t go to the first
// surface in that order, spheres before billboards (the strict `<` there). A secondary ray
// skips the surface it leaves: it leaves a sphere on its outer side (or a billboard's plane)
// moving away, so the only "hit" there would be the t ~ 0 rounding artefact that offsetting
// the origin otherwise has to avoid.
Hit intersect(const Scene& scene, const Ray& ray, double t_max, SurfaceId leaving, TraceObserver* observer) {
    Hit nearest;
    double nearest_t = t_max;
    for_each_kind([&](auto kind) {
        decltype(kind)::reference_nearest(scene, ray, leaving, nearest_t, nearest, observer);
    });
    if (observer) observer->nearest_found(nearest);
    return nearest;
}

Hit intersect_in_view(const Scene& scene, const Ray& ray, TraceObserver* observer) {
    if (ray.t_start == 0 && ray.t_end == kInfinity) return intersect(scene, ray, kInfinity, {}, observer);
    const Ray kept{ray.origin + ray.direction * ray.t_start, ray.direction};
    if (observer) observer->search_clipped(kept, ray.t_start, ray.t_end);
    Hit hit = intersect(scene, kept, ray.t_end - ray.t_start, {}, observer);
    if (hit.kind != HitKind::None) hit.t += ray.t_start;
    return hit;
}

Hit intersect(const Scene& scene, const Ray& ray, double t_max, SurfaceId leaving) {
    return intersect(scene, ray, t_max, leaving, nullptr);
}

}  // namespace clr::reference
