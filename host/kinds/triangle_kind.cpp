#include "kinds/triangle_kind.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "render/device_structs.h"
#include "render/object_bounds.h"
#include "scene/mesh_loader.h"

namespace clr {

Box3 TriangleKind::box(const Triangle& triangle, const Vec3& shift, Vec3& centroid) {
    Box3 box;
    for (const Vec3& corner : triangle.corners) box.grow(corner - shift);
    centroid = (box.lower + box.upper) * 0.5;
    return box;
}

PixelBounds TriangleKind::pixel_bounds(const ObjectBounds& view, const Triangle& triangle, const Vec3& object_origin) {
    const Vec3 eye = view.eye() - object_origin;
    PixelBounds bounds;
    for (const Vec3& corner : triangle.corners) view.add(corner, eye, bounds);
    if (ObjectBounds::reaches_behind_eye(bounds)) {
        bounds = {};
        view.add_clipped(triangle.corners.data(), 3, eye, bounds);
    }
    return bounds;
}

// The larger of the distances from the eye to the triangle's plane and to its box: every
// point of the triangle is at least that far. The plane alone says little of a triangle seen
// edge on, whose plane passes near the eye however far the triangle lies. (The loader keeps no
// triangle without area, whose plane is undefined.)
double TriangleKind::least_distance(const ObjectBounds& view, const Triangle& triangle, const Vec3& object_origin) {
    const auto& c = triangle.corners;
    const Vec3 eye = view.eye() - object_origin;
    // Compared as squares, with one square root for the larger: binning calls this for every
    // triangle of every frame.
    Vec3 centroid;
    const double to_box2 = box(triangle, {}, centroid).squared_distance_to(eye);
    const Vec3 normal = cross(c[1] - c[0], c[2] - c[0]);
    const double normal2 = dot(normal, normal);
    const double offset = dot(eye - c[0], normal);
    const double to_plane2 = normal2 > 0 ? offset * offset / normal2 : 0;
    return std::sqrt(std::max(to_box2, std::isfinite(to_plane2) ? to_plane2 : 0.0));
}

// Every mesh has a triangle (the loader refuses a mesh that draws nothing), so a scene's mesh
// indices fit the 24 bits that ClrTriangle::mesh_flags has for them.
static_assert(kMaxSceneTriangles <= (std::size_t(1) << (32 - CLR_TRIANGLE_MESH_SHIFT)));
// And every surface flag fits the bits below the mesh's.
static_assert(((CLR_SURFACE_MIRROR | CLR_SURFACE_TEXTURED | CLR_SURFACE_HOLES | CLR_SURFACE_NEAR_EYE) &
               ~CLR_TRIANGLE_OWN_FLAGS) == 0);

ClrTriangle TriangleKind::device(const Scene& scene, const Triangle& triangle, const Vec3& origin) {
    if (triangle.mesh >= scene.meshes.size() || triangle.mesh >= (1u << (32 - CLR_TRIANGLE_MESH_SHIFT)))
        throw std::logic_error("a triangle names mesh " + std::to_string(triangle.mesh) + " of " +
                               std::to_string(scene.meshes.size()));
    ClrTriangle out{};
    // Before move(), which marks a triangle near the eye in the flags' own bits.
    out.mesh_flags = triangle.mesh << CLR_TRIANGLE_MESH_SHIFT;
    move(out, triangle, origin);
    out.normals = triangle.normals < 0 ? -1 : triangle.normals * 3;
    return out;
}

ClrMeshSurface TriangleKind::mesh_surface(const Mesh& mesh) {
    ClrMeshSurface out{};
    out.color = to_float4(mesh.ambient);
    out.flags = mesh.is_mirror ? CLR_SURFACE_MIRROR : 0u;
    out.material = mesh.material;
    return out;
}

namespace {

Vec3 xyz(const cl_float4& v) { return {v.s[0], v.s[1], v.s[2]}; }

// ClrTriangle::longest_edge: each edge's |x| + |y| + |z| from the corners as stored, in double,
// a millionth larger before it is rounded to float, so that no float sum the kernels could make
// of the same corners exceeds it.
cl_float longest_edge(const ClrTriangle& device) {
    const Vec3 c0 = xyz(device.corner0), c1 = xyz(device.corner1), c2 = xyz(device.corner2);
    const auto norm1 = [](const Vec3& v) { return std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z); };
    return static_cast<cl_float>(std::max({norm1(c1 - c0), norm1(c2 - c1), norm1(c0 - c2)}) * (1 + 1e-6));
}

// The plane's normal (c1 - c0) x (c2 - c0) of the corners as stored, into the corners' w:
// the kernels decide the side of the plane by (c0 - o).n and d.n, as the reference finds t,
// and take the plane's t where it is the more exact (kernels/kinds/triangle.cl). Made from the edges
// scaled by the power of two that brings the longest near 1, so that it stays well inside
// float's range at every supported size (docs/scene-format.md, Numeric ranges); only its
// direction matters to t.
void store_plane_normal(ClrTriangle& device) {
    const Vec3 c0 = xyz(device.corner0);
    const Vec3 e1 = xyz(device.corner1) - c0, e2 = xyz(device.corner2) - c0;
    const double size = std::max({std::fabs(e1.x), std::fabs(e1.y), std::fabs(e1.z), std::fabs(e2.x),
                                  std::fabs(e2.y), std::fabs(e2.z)});
    Vec3 normal;
    if (size > 0) {
        const double scale = std::ldexp(1.0, -std::ilogb(size));
        normal = cross(e1 * scale, e2 * scale);
    }
    device.corner0.s[3] = static_cast<float>(normal.x);
    device.corner1.s[3] = static_cast<float>(normal.y);
    device.corner2.s[3] = static_cast<float>(normal.z);
}

// The plane's offset from the origin (the frame's eye) for the normal n as stored, into
// plane_offset: |n| times the eye's signed distance from the triangle's plane, in double from the
// unrounded corners. The kernels take a hit's t from it where it is the more exact
// (kernels/kinds/triangle.cl). So the plane the kernels see passes through the true plane's
// point nearest the eye, and the float normal's rounding (about 6e-8 of a radian) tilts it
// only about that point: from the corner, (c0 - eye).n put the plane of a triangle 1e8 across
// units off near the eye, as its corner is that far away.
//
// Where that distance is within rounding of 0, it is measured again from the corner nearest the
// eye, and is exactly 0 where the doubles put the eye in the plane through a corner or along an
// edge (a triple product of the corners relative to the eye that comes out 0): an eye on a
// mesh's vertex measured 7e-15 from the far corner, and a primary ray allows no slack, so half
// the view saw the triangle over everything.
void store_plane_offset(ClrTriangle& device, const Triangle& triangle, const Vec3& origin) {
    const Vec3 stored{device.corner0.s[3], device.corner1.s[3], device.corner2.s[3]};
    const auto& c = triangle.corners;
    const Vec3 plane = normalize(cross(c[1] - c[0], c[2] - c[0]));
    const Vec3 a = c[0] - origin;
    double distance = dot(a, plane);
    // Within rounding of the plane (rare; every triangle of every frame comes here), again from
    // the corner nearest the eye, and 0 where a triple product is.
    if (distance * distance <= 1e-24 * dot(a, a)) {
        const Vec3 b = c[1] - origin, d = c[2] - origin;
        Vec3 nearest = a;
        if (dot(b, b) < dot(nearest, nearest)) nearest = b;
        if (dot(d, d) < dot(nearest, nearest)) nearest = d;
        const bool in_plane = dot(cross(a, b), d) == 0 || dot(cross(b, d), a) == 0 || dot(cross(d, a), b) == 0;
        distance = in_plane ? 0.0 : dot(nearest, plane);
    }
    const double side = dot(stored, plane) < 0 ? -1.0 : 1.0;
    const double offset = side * distance * length(stored);
    // The loader keeps no triangle without area; should one come all the same, the corner's.
    device.plane_offset = static_cast<float>(std::isfinite(offset) ? offset : dot(c[0] - origin, stored));
}

// Whether the triangle is larger than an eighth of its distance from the origin (the frame's
// eye): its box's diagonal against the distance to its box, as squares (every triangle of every
// frame). Only such a triangle can have a hit that the kernels' plane_t_is_exacter() gives the
// plane's t: that needs the farthest corner along the ray twice as far as the hit, and a
// diagonal below 2 / sqrt(3) - 1 (0.155) of the distance keeps every corner nearer
// (kernels/kinds/triangle.cl).
bool near_eye(const Triangle& triangle, const Vec3& origin) {
    Vec3 centroid;
    const Box3 box = TriangleKind::box(triangle, origin, centroid);
    const Vec3 diagonal = box.upper - box.lower;
    return !(64 * dot(diagonal, diagonal) < box.squared_distance_to({}));
}

}  // namespace

void TriangleKind::move(ClrTriangle& device, const Triangle& triangle, const Vec3& origin) {
    device.corner0 = to_float4(triangle.corners[0] - origin);
    device.corner1 = to_float4(triangle.corners[1] - origin);
    device.corner2 = to_float4(triangle.corners[2] - origin);
    device.longest_edge = longest_edge(device);
    store_plane_normal(device);
    store_plane_offset(device, triangle, origin);
    device.mesh_flags = near_eye(triangle, origin) ? device.mesh_flags | CLR_SURFACE_NEAR_EYE
                                                   : device.mesh_flags & ~CLR_SURFACE_NEAR_EYE;
}

}  // namespace clr
