#include "kinds/sphere_kind.h"

#include <algorithm>
#include <array>
#include <limits>

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

// A sphere lies inside its axis-aligned box, whose projection bounds the sphere's.
PixelBounds SphereKind::pixel_bounds(const ObjectBounds& view, const Sphere& sphere, const Vec3&) {
    PixelBounds bounds;
    const double r = sphere.radius;
    const Vec3& eye = view.eye();
    if (view.box_clearly_in_front(sphere.center, r)) {
        // The box's corners in camera coordinates: the centre's, plus or minus the radius
        // along each axis (a few additions instead of projecting every corner anew).
        const Vec3& right = view.right_scaled();
        const Vec3& up = view.up_scaled();
        const Vec3& forward = view.forward();
        const Vec3 rel = sphere.center - eye;
        const Vec3 center{dot(rel, right), dot(rel, up), dot(rel, forward)};
        const std::array<Vec3, 3> axes = {Vec3{right.x, up.x, forward.x} * r, Vec3{right.y, up.y, forward.y} * r,
                                          Vec3{right.z, up.z, forward.z} * r};
        // Every corner lies in front of the eye, so the box's pixels reach as far as its
        // corners' extreme screen coordinates do (ObjectBounds::column_of()): the same bounds
        // as widening by each corner, with two conversions to pixels instead of eight. A
        // quotient that is not a number widens nothing, as in widen().
        // The x and y of a corner go through the same steps, two lanes of one vector (SSE2's
        // divpd on x86-64): half the divisions, each lane rounded as a double on its own.
        using XY = double __attribute__((vector_size(16)));
        constexpr double kInfinity = std::numeric_limits<double>::infinity();
        const XY center_xy = {center.x, center.y};
        const std::array<XY, 3> axes_xy = {XY{axes[0].x, axes[0].y}, XY{axes[1].x, axes[1].y}, XY{axes[2].x, axes[2].y}};
        XY least = {kInfinity, kInfinity}, most = -least;
        for (int bits = 0; bits < 8; ++bits) {
            const XY p = center_xy + (bits & 1 ? axes_xy[0] : -axes_xy[0]) + (bits & 2 ? axes_xy[1] : -axes_xy[1]) +
                         (bits & 4 ? axes_xy[2] : -axes_xy[2]);
            const double depth = center.z + (bits & 1 ? axes[0].z : -axes[0].z) + (bits & 2 ? axes[1].z : -axes[1].z) +
                                 (bits & 4 ? axes[2].z : -axes[2].z);
            const XY s = p / XY{depth, depth};
            least = s < least ? s : least;  // std::min(), std::max() lane by lane
            most = most < s ? s : most;
        }
        const double least_x = least[0], most_x = most[0], least_y = least[1], most_y = most[1];
        if (least_x <= most_x) {
            bounds.col_min = view.column_of(least_x);
            bounds.col_max = view.column_of(most_x);
        }
        if (least_y <= most_y) {
            bounds.row_min = view.row_of(most_y);
            bounds.row_max = view.row_of(least_y);
        }
        bounds.in_front = true;
        return bounds;
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
    move(out, sphere, origin);
    out.color = to_float4(sphere.ambient);
    out.flags = sphere.is_mirror ? CLR_SURFACE_MIRROR : 0u;
    return out;
}

void SphereKind::move(ClrSphere& device, const Sphere& sphere, const Vec3& origin) {
    device.center_radius = to_float4(sphere.center - origin, static_cast<float>(sphere.radius));
}

}  // namespace clr
