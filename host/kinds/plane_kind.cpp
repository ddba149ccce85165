#include "kinds/plane_kind.h"

#include "render/device_structs.h"

namespace clr {

ClrPlane PlaneKind::device(const Plane& plane, const Vec3& origin) {
    ClrPlane out{};
    move(out, plane, origin);
    out.normal = to_float4(plane.normal);
    out.color = to_float4(plane.ambient);
    out.flags = 0u;
    out.material = plane.material;
    return out;
}

void PlaneKind::move(ClrPlane& device, const Plane& plane, const Vec3& origin) {
    device.point = to_float4(plane.point - origin);
}

}  // namespace clr
