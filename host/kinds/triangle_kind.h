// The triangle kind on the host, in one place: which objects of a frame are mesh triangles,
// their bounds for the BVH, their screen bounds for the screen tiles, their device struct,
// and the shading rule. The kernels' half is kernels/kinds/triangle.cl; the list of kinds is
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

struct TriangleKind {
    using Object = Triangle;
    static constexpr int kHit = CLR_HIT_TRIANGLE;
    // The shading rule: in a lit scene the sun lights a mesh as it lights a sphere (its
    // ambient colour times max(0, n.l) and the sun's visibility, n facing the ray;
    // docs/scene-format.md, Meshes).
    static constexpr bool kLit = true;
    static constexpr bool kBounded = true;  // in the BVH and the screen tiles

    static std::size_t count(const Scene& scene) { return scene.triangles.size(); }
    static std::size_t count(const FrameGeometry& frame) { return frame.triangles().size(); }
    static const Triangle& object(const FrameGeometry& frame, std::size_t i) { return frame.triangles()[i]; }
    static Vec3 origin(const FrameGeometry&, std::size_t) { return {}; }

    // The BVH's bounds: the box around the three corners less `shift`, sorted by its centre.
    static Box3 box(const Triangle& triangle, const Vec3& shift, Vec3& centroid);

    // The screen tiles' bounds: the projection of the corners, clipped to the view when the
    // triangle reaches behind the eye; no hit is nearer than the triangle's plane.
    static PixelBounds pixel_bounds(const ObjectBounds& view, const Triangle& triangle, const Vec3& object_origin);
    static double least_distance(const ObjectBounds& view, const Triangle& triangle, const Vec3& object_origin);

    // The device struct, corners relative to `origin` (its corner normals are
    // Scene::corner_normals, uploaded as they are), and the part of it that moves with the
    // frame's origin.
    static ClrTriangle device(const Scene& scene, const Triangle& triangle, const Vec3& origin);
    static void move(ClrTriangle& device, const Triangle& triangle, const Vec3& origin);
    // What its mesh gives each triangle's shading (ClrTriangle::mesh_flags names it).
    static ClrMeshSurface mesh_surface(const Mesh& mesh);

    // The double-precision reference's half (kinds/triangle_reference.cpp), as for spheres
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
    // Its Blinn-Phong material (Scene::materials).
    static std::uint32_t reference_material(const Scene& scene, int index) { return scene.meshes[scene.triangles[index].mesh].material; }
};

}  // namespace clr
