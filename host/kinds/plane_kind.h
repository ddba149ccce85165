// The plane kind on the host, in one place: which objects are planes, their device struct and
// the shading rule. A plane is unbounded (kBounded false): it lies in no BVH and no screen
// tile, and the kernels test every plane after the objects they cull (kernels/kinds/plane.cl).
// The list of kinds is kinds/kinds.h (docs/architecture.md, Adding a primitive kind).
#pragma once

#include <cstddef>
#include <vector>

#include "render/frame_geometry.h"
#include "scene/scene.h"
#include "shared/clr_types.h"

namespace clr {

namespace reference {
enum class ColourSource;
enum class HitKind;
struct Hit;
struct Ray;
struct SurfaceId;
class TraceObserver;
}  // namespace reference

struct PlaneKind {
    using Object = Plane;
    static constexpr int kHit = CLR_HIT_PLANE;
    // Lit as spheres are (docs/scene-format.md, Lights and materials), seen from both sides.
    static constexpr bool kLit = true;
    // No box holds an infinite plane: the BVH and the screen tiles leave planes out.
    static constexpr bool kBounded = false;

    static std::size_t count(const Scene& scene) { return scene.planes.size(); }

    // The device struct, its point relative to `origin`, and the part that moves with it.
    static ClrPlane device(const Plane& plane, const Vec3& origin);
    static void move(ClrPlane& device, const Plane& plane, const Vec3& origin);

    // The double-precision reference's half (kinds/plane_reference.cpp), as for spheres
    // (sphere_kind.h); the normal faces `direction`'s ray.
    static reference::HitKind reference_kind();
    static void reference_nearest(const Scene& scene, const reference::Ray& ray, const reference::SurfaceId& leaving,
                                  double& nearest_t, reference::Hit& nearest, reference::TraceObserver* observer);
    static double reference_margin(const Scene& scene, const reference::Ray& ray, double t_max,
                                   const reference::SurfaceId& leaving, std::vector<double>& hit_ts);
    static Vec3 reference_normal(const Scene& scene, int index, const Vec3& point, const Vec3& direction);
    static bool reference_is_mirror(const Scene& scene, int index);
    static reference::ColourSource reference_own_color(const Scene& scene, const reference::Hit& hit, Color& colour);
    static const Color& reference_ambient(const Scene& scene, int index);
    static std::uint32_t reference_material(const Scene& scene, int index) { return scene.planes[index].material; }
};

}  // namespace clr
