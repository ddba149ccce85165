#include "kinds/sphere_kind.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "render/device_structs.h"
#include "render/object_bounds.h"

namespace clr {

Box3 SphereKind::box(const Sphere& sphere, const Vec3& shift, Vec3& centroid) {
    const Vec3 r{sphere.radius, sphere.radius, sphere.radius};
    const Vec3 center = sphere.center - shift;
    centroid = center;
    Box3 box;
    box.grow(center - r);
    box.grow(center + r);
    return box;
}

namespace {

// The least and greatest slopes s of the planes x = s z through the eye (the origin) that touch
// a sphere of radius r around (x, z) in a plane's coordinates, z > r: those at distance r
// from the centre, (x - s z)^2 = r^2 (1 + s^2). The sphere lies between them. false where the
// doubles overflow (coordinates beyond 1e150), for the caller's coarser bounds.
bool touching_slopes(double x, double z, double r, double& least, double& most) {
    const double z_r = (z - r) * (z + r);  // z^2 - r^2 without cancelling, > 0
    const double along = x * z, across = r * std::sqrt(x * x + z_r);
    least = (along - across) / z_r;
    most = (along + across) / z_r;
    return std::isfinite(least) && std::isfinite(most);
}

}  // namespace

// A sphere wholly in front of the eye: the rectangle around its silhouette, whose edges are
// where the planes through the eye along the screen's columns (and rows) touch the sphere;
// exact up to rounding, which the screen tiles' margin covers. The projection of the sphere's
// box had been used: it reaches up to (1 + |t|) / sqrt(1 + t^2) times as far from a small
// sphere's centre at t = x / depth (1.37 times at the edge of a 60 degree view), so every row
// within it tested the sphere for nothing, and it took sixteen divisions (docs/benchmarks.md,
// Binning 100,000 spheres). Otherwise, the projection of the sphere's axis-aligned box.
PixelBounds SphereKind::pixel_bounds(const ObjectBounds& view, const Sphere& sphere, const Vec3&) {
    PixelBounds bounds;
    const double r = sphere.radius;
    const Vec3& eye = view.eye();
    if (view.box_clearly_in_front(sphere.center, r)) {
        const Vec3 rel = sphere.center - eye;
        const double depth = dot(rel, view.forward());  // > r: its box is in front of the eye
        double least_x, most_x, least_y, most_y;
        if (touching_slopes(dot(rel, view.right_unit()), depth, r, least_x, most_x) &&
            touching_slopes(dot(rel, view.up_unit()), depth, r, least_y, most_y)) {
            bounds.col_min = view.column_of(least_x * view.screen_x_per_unit());
            bounds.col_max = view.column_of(most_x * view.screen_x_per_unit());
            bounds.row_min = view.row_of(most_y * view.screen_y_per_unit());
            bounds.row_max = view.row_of(least_y * view.screen_y_per_unit());
            bounds.in_front = true;
            return bounds;
        }
    }
    auto corner = [&](int bits) {
        return sphere.center + Vec3{bits & 1 ? r : -r, bits & 2 ? r : -r, bits & 4 ? r : -r};
    };
    for (int bits = 0; bits < 8; ++bits) view.add(corner(bits), eye, bounds);
    if (!ObjectBounds::reaches_behind_eye(bounds)) return bounds;
    // Reaching behind the eye: the box's faces are clipped (a ray from outside the box enters
    // through one; from inside, every direction meets one).
    bounds = {};
    for (int axis = 0; axis < 3; ++axis) {
        const int u = 1 << ((axis + 1) % 3), v = 1 << ((axis + 2) % 3);
        for (int side : {0, 1 << axis}) {
            const std::array<Vec3, 4> face = {corner(side), corner(side | u), corner(side | u | v), corner(side | v)};
            view.add_clipped(face.data(), 4, eye, bounds);
        }
    }
    return bounds;
}

double SphereKind::least_distance(const ObjectBounds& view, const Sphere& sphere, const Vec3&) {
    return std::max(0.0, length(sphere.center - view.eye()) - sphere.radius);
}

ClrSphere SphereKind::device(const Sphere& sphere, const Vec3& origin) {
    ClrSphere out{};
    // Before move(), which stores the eye's power in the colour's w and marks a sphere near the
    // eye in the flags.
    out.color = to_float4(sphere.ambient);
    out.flags = sphere.is_mirror ? CLR_SURFACE_MIRROR : 0u;
    move(out, sphere, origin);
    out.material = sphere.material;
    return out;
}

// The centre relative to the origin (the frame's eye), and in the colour's w the origin's power
// |origin - centre|^2 - r^2, in double and as (d - r)(d + r): the kernels take it where their
// own, from the centre rounded to float, cancels (kernels/kinds/sphere.cl, sphere_power()): an
// eye 1.4 above a ground sphere of radius 1e8, whose squares round by 6e8, saw nothing.
void SphereKind::move(ClrSphere& device, const Sphere& sphere, const Vec3& origin) {
    device.center_radius = to_float4(sphere.center - origin, static_cast<float>(sphere.radius));
    const double distance = length(origin - sphere.center);
    const double power = (distance - sphere.radius) * (distance + sphere.radius);
    device.color.s[3] = static_cast<float>(power);
    // The kernels' test can choose the eye's power only where 4096 |power| < distance^2 + r^2
    // (sphere_power()); half that, for rounding, marks the spheres that run it.
    const bool near_eye = 2048 * std::fabs(power) < distance * distance + sphere.radius * sphere.radius;
    device.flags = near_eye ? device.flags | CLR_SURFACE_NEAR_EYE : device.flags & ~CLR_SURFACE_NEAR_EYE;
}

}  // namespace clr
