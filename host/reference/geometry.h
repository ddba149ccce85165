// Internal to the reference renderer: the ray-surface geometry that intersect(),
// decision_margin() and trace() share. Written from the lecture's formulas (ray-sphere
// quadratic, ray-plane t, billboard coordinates) and the conventions of docs/scene-format.md,
// in double precision.
#pragma once

#include "reference/reference.h"

namespace clr::reference::detail {

inline Vec3 point_at(const Ray& ray, double t) { return ray.origin + ray.direction * t; }

// Both roots of |o + t d - c|^2 = r^2, i.e. A t^2 + B t + C = 0 with A = 1 (d is unit).
struct SphereRoots {
    bool real = false;  // false: the ray's line misses the sphere
    double t_near = 0;  // t_near <= t_far
    double t_far = 0;
    // The coefficients as computed, for an explanation of the test (trace_observer.h):
    // B/2 = d.(o-c), C, and (B/2)^2 - AC, a quarter of the lecture's discriminant.
    double half_b = 0;
    double c = 0;
    double quarter_discriminant = 0;
};
SphereRoots sphere_roots(const Sphere& sphere, const Ray& ray);

// The smallest root in (0, t_max), or kInfinity. With the origin inside, that is the far root.
double sphere_hit_t(const Sphere& sphere, const Ray& ray, double t_max);

// Whether surface (kind, index) is the one a secondary ray leaves.
inline bool is_leaving(SurfaceId leaving, HitKind kind, int index) {
    return leaving.kind == kind && (leaving.index == index || (leaving.also >= 0 && leaving.also == index));
}

// Where a ray's line meets a billboard's plane, in billboard coordinates:
// P = UL + a(UR-UL) + b(LL-UL) = o + t d. `meets` is false for a ray parallel to the plane.
struct PlaneHit {
    bool meets = false;
    double t = 0;  // may be <= 0: the plane is behind the origin
    double a = 0, b = 0;
};
PlaneHit billboard_plane_hit(const Billboard& billboard, const Ray& ray);

inline bool inside_unit_square(double a, double b) { return a >= 0 && a <= 1 && b >= 0 && b <= 1; }

// A ray tested against a triangle (kinds/triangle_reference.cpp): where it meets the
// triangle's plane, and the point's barycentric coordinates there (weights[i] of corner i,
// each the orientation test of the opposite edge over |n|^2).
struct TriangleTest {
    bool meets_plane = false;  // false: the ray runs parallel to the plane
    double t = 0;
    double weights[3] = {0, 0, 0};
    bool inside = false;  // every weight >= 0
    bool ahead = false;   // t beyond the secondary ray's rounding gap (> 0 for a primary ray)
};

// Billboards that show an image (a mirror ignores its image: docs/scene-format.md,
// Conventions: Mirrors).
inline bool is_textured(const Billboard& billboard) { return billboard.image && !billboard.is_mirror; }

// The texel under billboard coordinates (a, b): column floor(a W), row floor(b H), clamped.
struct Texel {
    int col = 0, row = 0;
};
Texel texel_at(const Image& image, double a, double b);
bool texel_is_opaque(const Image& image, const Texel& texel);
Color texel_color(const Image& image, const Texel& texel);

// Unit normal of the side from which the image reads correctly: (LL-UL) x (UR-UL).
Vec3 billboard_front_normal(const Billboard& billboard);

// What trace() needs to know about the surface a hit landed on.
struct SurfacePoint {
    Vec3 point;
    Vec3 normal;  // unit; a sphere's outward normal, a billboard's front normal, a triangle's facing the ray
    bool is_mirror = false;
    SurfaceId id;
};
SurfacePoint surface_at(const Scene& scene, const Ray& ray, const Hit& hit);
// The Blinn-Phong material of the surface `hit` landed on (Scene::materials[0] for a kind
// that has none).
const Material& material_of(const Scene& scene, const Hit& hit);

// Whether the sun lights surfaces of `kind`: each kind's shading rule (host/kinds/).
bool is_lit(HitKind kind);

// A ray sees a surface's front side when it travels against the normal.
inline bool sees_front(const Ray& ray, const SurfacePoint& surface) { return dot(ray.direction, surface.normal) < 0; }

// The mirror ray r = d - 2(d.n)n, leaving from the hit point.
Ray reflect(const Ray& ray, const SurfacePoint& surface);

// The unit direction and distance from a lit point to the sun; `exists` is false when the
// point is the sun's own location (no direction to speak of).
struct SunDirection {
    bool exists = false;
    Vec3 l;
    double distance = 0;
};
SunDirection sun_direction(const Scene& scene, const Vec3& point);

// decision_margin() for one ray segment (0, t_max) that skips `leaving`. With
// `depth_order_matters`, two accepted hits at nearly the same depth count too (they do not
// for a shadow ray, where any hit gives the same answer).
double ray_margin(const Scene& scene, const Ray& ray, double t_max, SurfaceId leaving, bool depth_order_matters);

}  // namespace clr::reference::detail
