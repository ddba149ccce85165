// Ray-sphere and ray-billboard geometry of the reference renderer (lecture: "Ray-Sphere
// Intersection", "Ray-Plane Intersection", "Finding the color of a point on a billboard").
#include "reference/geometry.h"

#include <algorithm>
#include <cmath>

#include "kinds/kinds.h"

namespace clr::reference::detail {

SphereRoots sphere_roots(const Sphere& sphere, const Ray& ray) {
    // A t^2 + B t + C = 0 with A = d.d = 1, B = 2 d.(o-c), C = (o-c).(o-c) - r^2.
    const Vec3 oc = ray.origin - sphere.center;
    const double half_b = dot(ray.direction, oc);
    const double c = dot(oc, oc) - sphere.radius * sphere.radius;

    // The discriminant (B/2)^2 - AC equals r^2 - |closest|^2, where `closest` runs from the
    // centre to the line's point nearest to it. That form avoids subtracting two large,
    // nearly equal numbers when the sphere is far away and small (Ray Tracing Gems ch. 7).
    const Vec3 closest = oc - ray.direction * half_b;
    const double discriminant = sphere.radius * sphere.radius - dot(closest, closest);
    SphereRoots roots;
    roots.half_b = half_b;
    roots.c = c;
    roots.quarter_discriminant = discriminant;
    if (discriminant < 0) return roots;

    // Compute the root without cancellation first and get the other from t_near t_far = C.
    const double root = std::sqrt(discriminant);
    roots.real = true;
    if (half_b < 0) {
        roots.t_far = -half_b + root;
        roots.t_near = c / roots.t_far;
    } else if (half_b > 0) {
        roots.t_near = -half_b - root;
        roots.t_far = c / roots.t_near;
    } else {
        roots.t_near = -root;
        roots.t_far = root;
    }
    return roots;
}

double sphere_hit_t(const Sphere& sphere, const Ray& ray, double t_max) {
    const SphereRoots roots = sphere_roots(sphere, ray);
    if (!roots.real) return kInfinity;
    const double t = roots.t_near > 0 ? roots.t_near : roots.t_far;
    return (t > 0 && t < t_max) ? t : kInfinity;
}

PlaneHit billboard_plane_hit(const Billboard& billboard, const Ray& ray) {
    const Vec3 edge_a = billboard.upper_right - billboard.upper_left;  // a runs UL -> UR
    const Vec3 edge_b = billboard.lower_left - billboard.upper_left;   // b runs UL -> LL
    const Vec3 n = cross(edge_b, edge_a);                              // length does not matter here

    // t = ((UL - o).n) / (d.n); a ray parallel to the plane never meets it.
    const double d_dot_n = dot(ray.direction, n);
    if (d_dot_n == 0) return {};
    PlaneHit hit;
    hit.meets = true;
    hit.t = dot(billboard.upper_left - ray.origin, n) / d_dot_n;

    // r = P - UL = a edge_a + b edge_b. Dotting with both edges gives the 2x2 system
    // G (a, b) = (r.edge_a, r.edge_b) with the Gram matrix G, solved by Cramer's rule; unlike
    // projecting on unit edges, this is right for parallelograms that are not rectangles.
    const Vec3 r = point_at(ray, hit.t) - billboard.upper_left;
    const double g_aa = dot(edge_a, edge_a);
    const double g_ab = dot(edge_a, edge_b);
    const double g_bb = dot(edge_b, edge_b);
    const double r_a = dot(r, edge_a);
    const double r_b = dot(r, edge_b);
    const double det = g_aa * g_bb - g_ab * g_ab;  // > 0 for the non-degenerate corners a scene has
    if (det == 0) return {};
    hit.a = (r_a * g_bb - r_b * g_ab) / det;
    hit.b = (g_aa * r_b - g_ab * r_a) / det;
    return hit;
}

Texel texel_at(const Image& image, double a, double b) {
    // a = 1 or b = 1 lands one past the last texel: the clamp keeps the edge inside.
    Texel texel;
    texel.col = std::clamp(static_cast<int>(std::floor(a * image.width)), 0, image.width - 1);
    texel.row = std::clamp(static_cast<int>(std::floor(b * image.height)), 0, image.height - 1);
    return texel;
}

bool texel_is_opaque(const Image& image, const Texel& texel) { return image.at(texel.col, texel.row, 3) == 255; }

Color texel_color(const Image& image, const Texel& texel) {
    return Color(image.at(texel.col, texel.row, 0), image.at(texel.col, texel.row, 1),
                 image.at(texel.col, texel.row, 2)) /
           255.0;
}

Vec3 billboard_front_normal(const Billboard& billboard) {
    return normalize(cross(billboard.lower_left - billboard.upper_left, billboard.upper_right - billboard.upper_left));
}

SurfacePoint surface_at(const Scene& scene, const Ray& ray, const Hit& hit) {
    SurfacePoint surface;
    surface.point = point_at(ray, hit.t);
    surface.id = {hit.kind, hit.index};
    for_each_kind([&](auto kind) {
        using Kind = decltype(kind);
        if (hit.kind != Kind::reference_kind()) return;
        surface.normal = Kind::reference_normal(scene, hit.index, surface.point, ray.direction);
        surface.is_mirror = Kind::reference_is_mirror(scene, hit.index);
    });
    return surface;
}

const Material& material_of(const Scene& scene, const Hit& hit) {
    std::uint32_t index = 0;
    for_each_kind([&](auto kind) {
        if (hit.kind == decltype(kind)::reference_kind()) index = decltype(kind)::reference_material(scene, hit.index);
    });
    return scene.materials[index];
}

bool is_lit(HitKind kind) {
    bool lit = false;
    for_each_kind([&](auto each) { lit |= kind == decltype(each)::reference_kind() && decltype(each)::kLit; });
    return lit;
}

Ray reflect(const Ray& ray, const SurfacePoint& surface) {
    const Vec3& d = ray.direction;
    const Vec3& n = surface.normal;
    // Unit d and n give a unit r already; normalizing keeps rounding from accumulating
    // over many bounces.
    return {surface.point, normalize(d - n * (2 * dot(d, n)))};
}

SunDirection sun_direction(const Scene& scene, const Vec3& point) {
    const Vec3 to_sun = scene.sun_location - point;
    SunDirection sun;
    sun.distance = length(to_sun);
    sun.exists = sun.distance > 0;
    if (sun.exists) sun.l = to_sun / sun.distance;
    return sun;
}

}  // namespace clr::reference::detail
