// The billboard kind on the host, in one place: which objects of a frame are billboards (the
// scene's own, then its impostors as placed), their bounds for the BVH, their screen bounds
// for the screen tiles, their device struct, and the shading rule. The kernels' half is
// kernels/kinds/billboard.cl; the list of kinds is kinds/kinds.h (docs/architecture.md,
// Adding a primitive kind).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/box3.h"
#include "render/frame_geometry.h"
#include "render/texture_slot.h"
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

struct BillboardKind {
    using Object = Billboard;
    static constexpr int kHit = CLR_HIT_BILLBOARD;  // ClrHit.kind, and the kind of its scene items
    // The shading rule: billboards are pictures, never lit (docs/scene-format.md,
    // Conventions: Lighting and shadows).
    static constexpr bool kLit = false;
    static constexpr bool kBounded = true;  // in the BVH and the screen tiles

    // The scene's billboards (impostors are billboards in every frame), and the frame's in the
    // kernels' order; a placed impostor's corners are relative to the eye it was placed for.
    static std::size_t count(const Scene& scene) { return scene.billboards.size() + scene.impostors.size(); }
    static std::size_t count(const FrameGeometry& frame) { return frame.billboard_count(); }
    static const Billboard& object(const FrameGeometry& frame, std::size_t i) { return frame.billboard(i); }
    static Vec3 origin(const FrameGeometry& frame, std::size_t i) { return frame.billboard_origin(i); }

    // The BVH's bounds: the box around the four corners, with positions less `shift`, and
    // the point the BVH sorts it by (its centre).
    static Box3 box(const Billboard& billboard, const Vec3& shift, Vec3& centroid);

    // The screen tiles' bounds (render/object_bounds.h): a parallelogram projects inside the
    // hull of its corners, which are relative to `object_origin`; clipped to the view when it
    // reaches behind the eye. No hit is nearer than its plane.
    static PixelBounds pixel_bounds(const ObjectBounds& view, const Billboard& billboard, const Vec3& object_origin);
    static double least_distance(const ObjectBounds& view, const Billboard& billboard, const Vec3& object_origin);

    // The device struct, positions relative to `origin`, showing the image at `texture` (null:
    // its flat colour), and the part of it that moves with the frame's origin.
    static ClrBillboard device(const Billboard& billboard, const TextureSlot* texture, const Vec3& origin);
    static void move(ClrBillboard& device, const Billboard& billboard, const Vec3& origin);

    // The double-precision reference's half (kinds/billboard_reference.cpp, from the lecture's
    // formulas in reference/geometry), for reference::intersect(), decision_margin() and
    // trace(): the kind's reference::HitKind; a test of the scene's billboards but `leaving`
    // that keeps in `nearest` any hit nearer than `nearest_t` (telling `observer`); the
    // billboards' decision margin on the segment (0, t_max), adding their accepted hits' t to
    // `hit_ts`; the unit front normal at a point of billboard `index`, and its mirror flag; its
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
    static std::uint32_t reference_material(const Scene&, int) { return 0; }
};

}  // namespace clr
