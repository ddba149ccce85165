// Reference shading: what colour a ray sees (docs/scene-format.md, Conventions: Lighting and
// shadows; docs/scene-format.md, Conventions: Mirrors).
#include "reference/geometry.h"

namespace clr::reference {

using detail::SurfacePoint;

namespace {

const Color kBlack{0, 0, 0};

// 1 if nothing opaque lies between the point and the sun, else 0. The shadow ray skips the
// sphere it starts on: it leaves it on the lit (outer) side, so it cannot meet it again.
double sun_visibility(const Scene& scene, const SurfacePoint& surface, const detail::SunDirection& sun) {
    const Ray shadow_ray{surface.point, sun.l};
    const Hit blocker = intersect(scene, shadow_ray, sun.distance, surface.id);
    return blocker.kind == HitKind::None ? 1.0 : 0.0;
}

// ambient * max(0, n.l) * s; the shadow ray is only worth casting when n.l > 0.
Color lit_sphere_color(const Scene& scene, const Sphere& sphere, const SurfacePoint& surface) {
    const auto sun = detail::sun_direction(scene, surface.point);
    if (!sun.exists) return kBlack;
    const double cosine = dot(surface.normal, sun.l);
    if (cosine <= 0) return kBlack;
    return sphere.ambient * (cosine * sun_visibility(scene, surface, sun));
}

Color billboard_color(const Billboard& billboard, const Hit& hit) {
    if (!detail::is_textured(billboard)) return billboard.ambient;
    // intersect() only returns opaque texels, so the texel's alpha needs no blending here.
    return detail::texel_color(*billboard.image, detail::texel_at(*billboard.image, hit.a, hit.b));
}

// The colour of a surface that is not a mirror. Billboards are pictures: never lit.
Color surface_color(const Scene& scene, const Hit& hit, const SurfacePoint& surface) {
    if (hit.kind == HitKind::Billboard) return billboard_color(scene.billboards[hit.index], hit);
    const Sphere& sphere = scene.spheres[hit.index];
    return scene.lit() ? lit_sphere_color(scene, sphere, surface) : sphere.ambient;
}

}  // namespace

// Mirrors make the path a chain of rays, so a loop over reflections replaces recursion.
Color trace(const Scene& scene, const Ray& ray) {
    Ray current = ray;
    SurfaceId leaving;
    for (int reflections = 0;; ++reflections) {
        const Hit hit = intersect(scene, current, kInfinity, leaving);
        if (hit.kind == HitKind::None) return scene.background;
        const SurfacePoint surface = detail::surface_at(scene, current, hit);
        if (!surface.is_mirror) return surface_color(scene, hit, surface);
        if (!detail::sees_front(current, surface)) return kBlack;  // the back of a mirror
        // MaxDepth reflections are allowed; a ray that needs one more sees the background.
        if (reflections >= scene.max_depth) return scene.background;
        current = detail::reflect(current, surface);
        leaving = surface.id;
    }
}

}  // namespace clr::reference
