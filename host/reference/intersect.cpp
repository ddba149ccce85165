// Reference nearest-hit search over all spheres and billboards.
#include "reference/geometry.h"
#include "reference/trace_observer.h"

namespace clr::reference {

using detail::billboard_plane_hit;
using detail::inside_unit_square;
using detail::is_leaving;
using detail::is_textured;
using detail::sphere_hit_t;
using detail::sphere_roots;
using detail::texel_at;
using detail::texel_is_opaque;

namespace {

// A billboard point counts as a hit unless it lies on a transparent texel, which lets the
// ray through as if the billboard were not there (docs/scene-format.md, Conventions: Billboards).
bool billboard_blocks(const Billboard& billboard, double a, double b) {
    if (!inside_unit_square(a, b)) return false;
    if (!is_textured(billboard)) return true;
    return texel_is_opaque(*billboard.image, texel_at(*billboard.image, a, b));
}

}  // namespace

// Ties in t go to the first surface in scene order, spheres before billboards (the strict
// `<` below). A secondary ray skips the surface it leaves: it leaves a sphere on its outer
// side (or a billboard's plane) moving away, so the only "hit" there would be the t ~ 0
// rounding artefact that offsetting the origin otherwise has to avoid.
Hit intersect(const Scene& scene, const Ray& ray, double t_max, SurfaceId leaving, TraceObserver* observer) {
    Hit nearest;
    double nearest_t = t_max;
    for (int i = 0; i < static_cast<int>(scene.spheres.size()); ++i) {
        if (is_leaving(leaving, HitKind::Sphere, i)) continue;
        const double t = sphere_hit_t(scene.spheres[i], ray, nearest_t);
        if (observer) observer->sphere_tested(i, sphere_roots(scene.spheres[i], ray), nearest_t, t);
        if (t < nearest_t) {
            nearest_t = t;
            nearest = {HitKind::Sphere, i, t, 0, 0};
        }
    }
    for (int i = 0; i < static_cast<int>(scene.billboards.size()); ++i) {
        if (is_leaving(leaving, HitKind::Billboard, i)) continue;
        const auto plane = billboard_plane_hit(scene.billboards[i], ray);
        const bool accepted = plane.meets && plane.t > 0 && plane.t < nearest_t &&
                              billboard_blocks(scene.billboards[i], plane.a, plane.b);
        if (observer) observer->billboard_tested(i, plane, nearest_t, accepted);
        if (!accepted) continue;
        nearest_t = plane.t;
        nearest = {HitKind::Billboard, i, plane.t, plane.a, plane.b};
    }
    if (observer) observer->nearest_found(nearest);
    return nearest;
}

Hit intersect(const Scene& scene, const Ray& ray, double t_max, SurfaceId leaving) {
    return intersect(scene, ray, t_max, leaving, nullptr);
}

}  // namespace clr::reference
