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
    move(out, billboard, origin);
    out.normal = to_float4(normalize(cross(edge_b, edge_a)));  // front: (LL-UL) x (UR-UL)
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
    return out;
}

void BillboardKind::move(ClrBillboard& device, const Billboard& billboard, const Vec3& origin) {
    device.corner = to_float4(billboard.upper_left - origin);
}

}  // namespace clr
