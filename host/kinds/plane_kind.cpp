#include "kinds/plane_kind.h"

#include "render/device_structs.h"

namespace clr {

ClrPlane PlaneKind::device(const Plane& plane, const Vec3& origin) {
    ClrPlane out{};
    out.normal = to_float4(plane.normal);  // before move(), which stores the plane's offset for it
    move(out, plane, origin);
    out.color = to_float4(plane.ambient);
    out.flags = 0u;
    out.material = plane.material;
    return out;
}

// The point relative to the origin (the frame's eye), and in its w the plane's offset
// (P0 - origin).n for the normal as stored, in double from the unrounded point: the kernels take
// it where the point, rounded to float relative to the eye, would put a plane through a far
// point units off (kernels/kinds/plane.cl, plane_offset()).
void PlaneKind::move(ClrPlane& device, const Plane& plane, const Vec3& origin) {
    device.point = to_float4(plane.point - origin);
    const Vec3 stored{device.normal.s[0], device.normal.s[1], device.normal.s[2]};
    device.point.s[3] = static_cast<float>(dot(plane.point - origin, plane.normal) * length(stored));
}

}  // namespace clr
