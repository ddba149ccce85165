// Reference shading: what colour a ray sees (docs/scene-format.md, Conventions: Lighting and
// shadows; docs/scene-format.md, Conventions: Mirrors).
#include "kinds/kinds.h"
#include "reference/geometry.h"
#include "reference/trace_observer.h"

namespace clr::reference {

using detail::SurfacePoint;

namespace {

const Color kBlack{0, 0, 0};

// The colour a ray returns, told to the observer when there is one.
Color found(TraceObserver* observer, ColourSource source, const Color& colour) {
    if (observer) observer->colour_found(source, colour);
    return colour;
}

// 1 if nothing opaque lies between the point and the sun, else 0. The shadow ray skips the
// sphere it starts on: it leaves it on the lit (outer) side, so it cannot meet it again.
double sun_visibility(const Scene& scene, const SurfacePoint& surface, const detail::SunDirection& sun, int depth,
                      TraceObserver* observer) {
    const Ray shadow_ray{surface.point, sun.l};
    if (observer) observer->ray_cast(RayRole::Shadow, depth, shadow_ray, sun.distance);
    const Hit blocker = intersect(scene, shadow_ray, sun.distance, surface.id, observer);
    return blocker.kind == HitKind::None ? 1.0 : 0.0;
}

// ambient * max(0, n.l) * s; the shadow ray is only worth casting when n.l > 0.
Color lit_color(const Scene& scene, const Color& ambient, const SurfacePoint& surface, int depth,
                TraceObserver* observer) {
    const auto sun = detail::sun_direction(scene, surface.point);
    if (!sun.exists) return found(observer, ColourSource::SunLit, kBlack);
    const double cosine = dot(surface.normal, sun.l);
    if (observer) observer->sun_seen(sun, cosine);
    if (cosine <= 0) return found(observer, ColourSource::SunLit, kBlack);
    return found(observer, ColourSource::SunLit, ambient * (cosine * sun_visibility(scene, surface, sun, depth, observer)));
}

// The colour of a surface that is not a mirror: lit by the sun when the scene is lit and its
// kind is (detail::is_lit: spheres; billboards are pictures), else its own colour (each
// kind's reference_own_color(): an ambient colour or a texel).
Color surface_color(const Scene& scene, const Hit& hit, const SurfacePoint& surface, int depth,
                    TraceObserver* observer) {
    const bool lit = scene.lit() && detail::is_lit(hit.kind);
    Color colour;
    ColourSource source = ColourSource::Background;
    for_each_kind([&](auto kind) {
        using Kind = decltype(kind);
        if (hit.kind != Kind::reference_kind()) return;
        if (lit)
            colour = lit_color(scene, Kind::reference_ambient(scene, hit.index), surface, depth, observer);
        else
            source = Kind::reference_own_color(scene, hit, colour);
    });
    return lit ? colour : found(observer, source, colour);
}

}  // namespace

// Mirrors make the path a chain of rays, so a loop over reflections replaces recursion.
Color trace(const Scene& scene, const Ray& ray, TraceObserver* observer) {
    Ray current = ray;
    SurfaceId leaving;
    for (int reflections = 0;; ++reflections) {
        if (observer)
            observer->ray_cast(reflections == 0 ? RayRole::Primary : RayRole::Reflected, reflections, current, kInfinity);
        const Hit hit = intersect(scene, current, kInfinity, leaving, observer);
        if (hit.kind == HitKind::None) return found(observer, ColourSource::Background, scene.background);
        const SurfacePoint surface = detail::surface_at(scene, current, hit);
        if (observer) observer->surface_reached(hit, surface);
        if (!surface.is_mirror) return surface_color(scene, hit, surface, reflections, observer);
        if (!detail::sees_front(current, surface))  // the back of a mirror
            return found(observer, ColourSource::BackOfMirror, kBlack);
        // MaxDepth reflections are allowed; a ray that needs one more sees the background.
        if (reflections >= scene.max_depth) return found(observer, ColourSource::DepthExhausted, scene.background);
        current = detail::reflect(current, surface);
        leaving = surface.id;
    }
}

Color trace(const Scene& scene, const Ray& ray) { return trace(scene, ray, nullptr); }

}  // namespace clr::reference
