#include "kinds/billboard_kind.h"

#include <array>
#include <cmath>

#include "render/device_structs.h"
#include "render/object_bounds.h"

namespace clr {

Box3 BillboardKind::box(const Billboard& billboard, const Vec3& shift, Vec3& centroid) {
    const Vec3 upper_left = billboard.upper_left - shift, upper_right = billboard.upper_right - shift;
    const Vec3 lower_left = billboard.lower_left - shift;
    const Vec3 lower_right = upper_right + (lower_left - upper_left);
    centroid = (upper_left + lower_right) * 0.5;
    Box3 box;
    for (const Vec3& corner : {upper_left, upper_right, lower_left, lower_right}) box.grow(corner);
    return box;
}

PixelBounds BillboardKind::pixel_bounds(const ObjectBounds& view, const Billboard& billboard,
                                        const Vec3& object_origin) {
    const Vec3 eye = view.eye() - object_origin;  // zero for impostors placed for this eye: exact
    PixelBounds bounds;
    const std::array<Vec3, 4> corners = {billboard.upper_left, billboard.upper_right,
                                         billboard.upper_right + (billboard.lower_left - billboard.upper_left),
                                         billboard.lower_left};
    for (const Vec3& corner : corners) view.add(corner, eye, bounds);
    if (ObjectBounds::reaches_behind_eye(bounds)) {
        bounds = {};
        view.add_clipped(corners.data(), 4, eye, bounds);
    }
    return bounds;
}

double BillboardKind::least_distance(const ObjectBounds& view, const Billboard& billboard, const Vec3& object_origin) {
    Vec3 normal = normalize(cross(billboard.upper_right - billboard.upper_left, billboard.lower_left - billboard.upper_left));
    return std::fabs(dot((view.eye() - object_origin) - billboard.upper_left, normal));
}

ClrBillboard BillboardKind::device(const Billboard& billboard, const TextureSlot* texture, const Vec3& origin) {
    // P = UL + a*edge_a + b*edge_b. With m = edge_a x edge_b, the dual vectors
    // (edge_b x m)/|m|^2 and (m x edge_a)/|m|^2 pick a and b out of P - UL by one dot product
    // each, for any parallelogram, and are computed here in double once per billboard.
    Vec3 edge_a = billboard.upper_right - billboard.upper_left;
    Vec3 edge_b = billboard.lower_left - billboard.upper_left;
    Vec3 m = cross(edge_a, edge_b);
    double m2 = dot(m, m);

    ClrBillboard out{};
    out.normal = to_float4(normalize(cross(edge_b, edge_a)));  // front: (LL-UL) x (UR-UL); move() sets its w
    out.dual_a = to_float4(cross(edge_b, m) / m2);
    out.dual_b = to_float4(cross(m, edge_a) / m2);
    out.color = to_float4(billboard.ambient);
    out.flags = billboard.is_mirror ? CLR_SURFACE_MIRROR : 0u;
    if (texture) {
        out.flags |= CLR_SURFACE_TEXTURED;
        out.texel_offset = texture->offset;
        out.texture_width = texture->width;
        out.texture_height = texture->height;
        if (texture->holes) out.flags |= CLR_SURFACE_HOLES;  // only these need alpha tests
    }
    move(out, billboard, origin);  // last: it marks a billboard near the eye in the flags
    return out;
}

// The corner relative to the origin (the frame's eye), and in the normal's w the plane's offset
// (UL - origin).n for the normal as stored: its length times the origin's signed distance from
// the plane, in double from the unrounded corners, so that the plane the kernels see passes
// through the true plane's point nearest the eye. The kernels take it where the corner, rounded
// to float relative to the eye, would put the plane of a billboard far larger than its distance
// units off (kernels/kinds/billboard.cl, billboard_offset()).
void BillboardKind::move(ClrBillboard& device, const Billboard& billboard, const Vec3& origin) {
    device.corner = to_float4(billboard.upper_left - origin);
    const Vec3 stored{device.normal.s[0], device.normal.s[1], device.normal.s[2]};
    const Vec3 plane = normalize(cross(billboard.lower_left - billboard.upper_left, billboard.upper_right - billboard.upper_left));
    const double side = dot(stored, plane) < 0 ? -1.0 : 1.0;
    const double offset = side * dot(billboard.upper_left - origin, plane) * length(stored);
    device.normal.s[3] = static_cast<float>(std::isfinite(offset) ? offset : dot(billboard.upper_left - origin, stored));
    // The kernels' test can choose the stored offset only where 4096 |offset| is below
    // (UL - eye).n summed by the components' magnitudes (billboard_offset()); half that, for
    // rounding, marks the billboards that run it.
    const Vec3 to_corner = billboard.upper_left - origin;
    const double spread = std::fabs(to_corner.x * stored.x) + std::fabs(to_corner.y * stored.y) +
                          std::fabs(to_corner.z * stored.z);
    const bool near_eye = 2048 * std::fabs(device.normal.s[3]) < spread;
    device.flags = near_eye ? device.flags | CLR_SURFACE_NEAR_EYE : device.flags & ~CLR_SURFACE_NEAR_EYE;
}

}  // namespace clr
