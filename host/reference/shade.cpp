// Reference shading: what colour a ray sees (docs/scene-format.md, Conventions: Lighting and
// shadows; docs/scene-format.md, Conventions: Mirrors).
#include <algorithm>
#include <cmath>
#include <optional>

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

Color times(const Color& a, const Color& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }

double norm1(const Vec3& v) { return std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z); }

// A hit on a triangle within t 2^-20 (|.|_1) of one of its corners becomes the lowest triangle
// of its mesh placement around that corner; else one within that band of one of its edge lines
// (|(P - a) x e|_1 <= band |e|_1) the lowest along that edge (Scene::triangle_ties); t stays.
// The tie's `other` is the lowest triangle there other than the one hit (that one where there
// is none): secondary rays leave both. The kernels settle alike (kernels/kinds/triangle.cl,
// triangle_settled_index()). Nothing (no settling) for a hit off every edge and corner.
std::optional<TieSettled> settled(const Scene& scene, const Ray& ray, const Hit& hit) {
    if (hit.kind != HitKind::Triangle || scene.triangle_ties.size() != scene.triangles.size()) return std::nullopt;
    const auto& c = scene.triangles[hit.index].corners;
    const auto& ties = scene.triangle_ties[hit.index];
    const Vec3 p = detail::point_at(ray, hit.t);
    TieSettled tie;
    tie.band = hit.t * 0x1p-20;
    const auto found = [&](bool at_corner, int k, double measure) {
        tie.at_corner = at_corner;
        tie.k = k;
        tie.measure = measure;
        tie.other = ties[at_corner ? 3 + k : k];
        tie.shaded = std::min(hit.index, tie.other);
        return tie;
    };
    for (int k = 0; k < 3; ++k)
        if (norm1(p - c[k]) <= tie.band) return found(true, k, norm1(p - c[k]));
    for (int k = 0; k < 3; ++k) {
        const Vec3& a = c[(k + 1) % 3];
        const Vec3 e = c[(k + 2) % 3] - a;
        const double across = norm1(cross(p - a, e));
        if (across <= tie.band * norm1(e)) return found(false, k, across / norm1(e));
    }
    return std::nullopt;
}


// The Blinn-Phong model with the scene's point lights (docs/scene-format.md, Lights and
// materials): the ambient colour plus, for each light with n.l > 0 that nothing opaque hides,
// its colour times k_d n.l + k_s max(0, n.h)^p, h = unit(l - d) halfway between the light and
// the eye. The shadow ray skips the surface it starts on.
Color phong_color(const Scene& scene, const Color& ambient, const Material& material, const Ray& ray,
                  const SurfacePoint& surface, int depth, TraceObserver* observer) {
    Color colour = ambient;
    for (int i = 0; i < static_cast<int>(scene.lights.size()); ++i) {
        const PointLight& light = scene.lights[i];
        const Vec3 to_light = light.position - surface.point;
        const double distance = length(to_light);
        const Vec3 l = to_light / distance;
        const double cosine = distance > 0 ? dot(surface.normal, l) : 0;  // a light at P lights nothing there
        if (cosine <= 0) {
            if (observer) observer->light_seen(i, cosine, false, 0);
            continue;
        }
        const Ray shadow_ray{surface.point, l};
        if (observer) observer->ray_cast(RayRole::Shadow, depth, shadow_ray, distance);
        const bool hidden = intersect(scene, shadow_ray, distance, surface.id, observer).kind != HitKind::None;
        if (hidden) {
            if (observer) observer->light_seen(i, cosine, true, 0);
            continue;
        }
        const Vec3 half = normalize(l - ray.direction);
        const double highlight = std::pow(std::max(0.0, dot(surface.normal, half)), material.phong_exponent);
        if (observer) observer->light_seen(i, cosine, false, highlight);
        colour = colour + times(light.color, material.diffuse * cosine + material.specular * highlight);
    }
    return found(observer, ColourSource::PhongLit, colour);
}

// The colour of a surface that is not a mirror: lit by the sun when the scene is lit and its
// kind is (detail::is_lit: spheres; billboards are pictures), else its own colour (each
// kind's reference_own_color(): an ambient colour or a texel).
Color surface_color(const Scene& scene, const Hit& hit, const Ray& ray, const SurfacePoint& surface, int depth,
                    TraceObserver* observer) {
    if (scene.lit_by_lights() && detail::is_lit(hit.kind)) {
        Color ambient;
        for_each_kind([&](auto kind) {
            if (hit.kind == decltype(kind)::reference_kind()) ambient = decltype(kind)::reference_ambient(scene, hit.index);
        });
        return phong_color(scene, ambient, detail::material_of(scene, hit), ray, surface, depth, observer);
    }
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

// Mirrors make the path a chain of rays, so a loop over reflections replaces recursion. An
// ideal mirror shows only what it reflects; a material with a mirror share k_m (lit by the
// scene's lights) adds its own colour, then k_m times what it reflects (`weight` carries the
// product of the shares so far).
Color trace(const Scene& scene, const Ray& ray, TraceObserver* observer) {
    Ray current = ray;
    SurfaceId leaving;
    Color sum{0, 0, 0}, weight{1, 1, 1};
    for (int reflections = 0;; ++reflections) {
        if (observer)
            observer->ray_cast(reflections == 0 ? RayRole::Primary : RayRole::Reflected, reflections, current, kInfinity);
        // The primary ray sees only the depths the camera's clip distances keep.
        const Hit found_hit = reflections == 0 ? intersect_in_view(scene, current, observer)
                                               : intersect(scene, current, kInfinity, leaving, observer);
        if (found_hit.kind == HitKind::None)
            return sum + times(weight, found(observer, ColourSource::Background, scene.background));
        const std::optional<TieSettled> tie = settled(scene, current, found_hit);
        Hit hit = found_hit;
        if (tie) {
            if (observer) observer->hit_settled(found_hit, *tie);
            hit.index = tie->shaded;
        }
        SurfacePoint surface = detail::surface_at(scene, current, hit);
        // Shaded as the settled triangle; its shadow and reflected rays leave both the one hit,
        // on whose plane the point lies, and the lowest other one there (the kernels' shade_hit()
        // alike).
        surface.id.index = found_hit.index;
        if (tie && tie->other != found_hit.index) surface.id.also = tie->other;
        if (observer) observer->surface_reached(hit, surface);
        if (!surface.is_mirror) {
            sum = sum + times(weight, surface_color(scene, hit, current, surface, reflections, observer));
            const Color& share = detail::material_of(scene, hit).mirror;
            if (!scene.lit_by_lights() || !detail::is_lit(hit.kind) || share == Color{0, 0, 0}) return sum;
            weight = times(weight, share);
        } else if (!detail::sees_front(current, surface)) {  // the back of a mirror
            return sum + times(weight, found(observer, ColourSource::BackOfMirror, kBlack));
        }
        // MaxDepth reflections are allowed; a ray that needs one more sees the background.
        if (reflections >= scene.max_depth)
            return sum + times(weight, found(observer, ColourSource::DepthExhausted, scene.background));
        current = detail::reflect(current, surface);
        leaving = surface.id;
    }
}

Color trace(const Scene& scene, const Ray& ray) { return trace(scene, ray, nullptr); }

}  // namespace clr::reference
