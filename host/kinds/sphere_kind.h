// The sphere kind on the host, in one place: which objects of a frame are spheres, their
// bounds for the BVH, their screen bounds for the screen tiles, their device struct, and the
// shading rule. The kernels' half is kernels/kinds/sphere.cl; the list of kinds is
// kinds/kinds.h (docs/architecture.md, Adding a primitive kind).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/box3.h"
#include "render/frame_geometry.h"
#include "scene/scene.h"
#include "shared/clr_types.h"

namespace clr {

class ObjectBounds;
struct PixelBounds;
namespace reference {
enum class ColourSource;
enum class HitKind;
struct Hit;
struct Ray;
struct SurfaceId;
class TraceObserver;
}  // namespace reference

struct SphereKind {
    using Object = Sphere;
    static constexpr int kHit = CLR_HIT_SPHERE;  // ClrHit.kind, and the kind of its scene items
    // The shading rule: in a lit scene the sun lights a sphere (its ambient colour times
    // max(0, n.l) and the sun's visibility; docs/scene-format.md, Conventions: Lighting and
    // shadows).
    static constexpr bool kLit = true;
    static constexpr bool kBounded = true;  // in the BVH and the screen tiles

    // The scene's spheres, and the frame's in the kernels' order; a sphere's position is in
    // scene coordinates (origin (0, 0, 0)).
    static std::size_t count(const Scene& scene) { return scene.spheres.size(); }
    static std::size_t count(const FrameGeometry& frame) { return frame.spheres().size(); }
    static const Sphere& object(const FrameGeometry& frame, std::size_t i) { return frame.spheres()[i]; }
    static Vec3 origin(const FrameGeometry&, std::size_t) { return {}; }

    // The BVH's bounds: the box around the sphere, with positions less `shift`, and the
    // point the BVH sorts it by (its centre).
    static Box3 box(const Sphere& sphere, const Vec3& shift, Vec3& centroid);

    // The screen tiles' bounds (render/object_bounds.h): the rectangle around the sphere's
    // silhouette where the sphere lies in front of the eye, else the projection of its box,
    // clipped to the view when it reaches behind the eye; and no hit is nearer than the
    // sphere's surface.
    static PixelBounds pixel_bounds(const ObjectBounds& view, const Sphere& sphere, const Vec3& object_origin);
    static double least_distance(const ObjectBounds& view, const Sphere& sphere, const Vec3& object_origin);

    // The device struct, positions relative to `origin`, and the part of it that moves with
    // the frame's origin.
    static ClrSphere device(const Sphere& sphere, const Vec3& origin);
    static void move(ClrSphere& device, const Sphere& sphere, const Vec3& origin);

    // The double-precision reference's half (kinds/sphere_reference.cpp, from the lecture's
    // formulas in reference/geometry), for reference::intersect(), decision_margin() and
    // trace(): the kind's reference::HitKind; a test of the scene's spheres but `leaving`
    // that keeps in `nearest` any hit nearer than `nearest_t` (telling `observer`); the
    // spheres' decision margin on the segment (0, t_max), adding their accepted hits' t to
    // `hit_ts`; the unit front normal at a point of sphere `index`, and its mirror flag; its
    // colour before lighting at `hit` and what gives it (reference/trace_observer.h), and the
    // ambient colour that the sun lights.
    static reference::HitKind reference_kind();
    static void reference_nearest(const Scene& scene, const reference::Ray& ray, const reference::SurfaceId& leaving,
                                  double& nearest_t, reference::Hit& nearest, reference::TraceObserver* observer);
    static double reference_margin(const Scene& scene, const reference::Ray& ray, double t_max,
                                   const reference::SurfaceId& leaving, std::vector<double>& hit_ts);
    static Vec3 reference_normal(const Scene& scene, int index, const Vec3& point, const Vec3& direction);
    static bool reference_is_mirror(const Scene& scene, int index);
    static reference::ColourSource reference_own_color(const Scene& scene, const reference::Hit& hit, Color& colour);
    static const Color& reference_ambient(const Scene& scene, int index);
    // Its Blinn-Phong material (Scene::materials).
    static std::uint32_t reference_material(const Scene& scene, int index) { return scene.spheres[index].material; }
};

}  // namespace clr
