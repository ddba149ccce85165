/* The triangle kind (ClrTriangle): a triangle of a mesh, seen from both sides. Where a ray
 * meets it, one ray and 16 at a time, its normal and its colour, as kinds/kinds.cl asks
 * every kind.
 *
 * The test is watertight: a ray through a vertex or an edge that triangles share hits at
 * least one of them, never none (docs/scene-format.md, Meshes). Each edge's side is first the
 * signed volume d.((p - o) x (q - o)) of the ray and the edge's corners p, q relative to the ray's
 * origin o, computed as d.((p - o) x (q - p)) (edge_volume_normal()); the three volumes are also
 * the hit's barycentric weights (Woop, Benthin and Wald 2013 use the same edge functions, after
 * a shear). Each rounds on its own, so near zero their signs could leave a ray through a
 * shared vertex or edge outside every triangle there, or put a ray through an open edge on
 * either side of it; a volume within a band of zero counts as zero (kinds/triangle_sides.cl).
 *
 * The hit's t blends the corners' distances along the ray by those weights: a convex blend,
 * accurate even where the ray grazes a far triangle. Where the origin lies in the
 * triangle's plane, though, t is 0 and the blend rounds to noise of either sign: an eye at
 * the height of a floor saw the floor over random pixels. So the side of the plane decides
 * first: the ray meets the triangle only where (c0 - o).n and d.n have one sign, n the
 * plane's normal that the host stores in the corners' w, as the reference finds it ((c0 - o).n
 * is exactly 0 for an eye on a floor along the axes); and where the plane says ahead but the
 * blend does not, t is the plane's (c0 - o).n / d.n.
 *
 * The blend rounds in proportion to the corners' distances along the ray, the plane's t in
 * proportion to the origin's distance from the plane: for a triangle far larger than its
 * distance (a ground triangle 1e8 across seen from 3 units) the blend's t was units off and
 * the floor speckled with false light. Each hit on such a triangle takes whichever of the two
 * is the more exact (plane_t_is_exacter()); the plane's offset may come from the host, computed
 * in double (triangle_offset()), since the corners themselves, rounded to float relative to the
 * eye, put such a plane units off. The host marks those triangles (CLR_SURFACE_NEAR_EYE: larger
 * than an eighth of their distance from the eye, where the test could choose the plane at all);
 * every other triangle takes the blend and its corner's offset without the test, which cost
 * about 8% of a mesh's primary rays. */
#ifndef CLR_KINDS_TRIANGLE_CL
#define CLR_KINDS_TRIANGLE_CL

#include "common/math.cl"
#include "common/scene_params.cl"
#include "kinds/triangle_sides.cl"
#include "packet/lane_masks.cl"
#include "packet/packet_types.cl"
#include "shared/clr_types.h"

/* A primary ray that starts on the near plane (docs/scene-format.md, Near and far clipping)
 * ignores hits nearer than this share of its origin's distance from the eye, rounding of its
 * start; it is far below a pixel's footprint at that distance. Primary rays from the eye
 * (0, 0, 0) ignore none. */
#if CLR_FEATURE_DOUBLE
#define CLR_TRIANGLE_SELF_GAP 1e-12
#else
#define CLR_TRIANGLE_SELF_GAP 1.5e-5f
#endif
/* A secondary ray leaves a point of a triangle, which float rounding puts a little off its
 * plane: a neighbour of that triangle in the same plane could then be met again where the ray
 * crosses that plane, at the rounding over the ray's slant, a speck of false shadow. Triangles
 * whose plane passes within rounding of the ray's origin, nearer than
 * CLR_TRIANGLE_PLANE_SLACK times its distance from the eye (|x| + |y| + |z|), are such
 * neighbours, and such a ray never meets them. A gap in t instead (hits nearer than 1.5e-5 of
 * that distance ignored) let a ray that grazes the plane through: a light 0.1 degrees over a
 * flat mesh left 0.09% of the image's pixels in a false shadow, 0.3% a light 0.03 degrees
 * up. Any other triangle counts at every t > 0: a mirror or shadow ray leaving a floor next to
 * a wall meets the wall however near (a gap for every triangle let rays through a concave
 * crease: a line of background along a mirror corner seen through a narrow lens). */
#if CLR_FEATURE_DOUBLE
#define CLR_TRIANGLE_PLANE_SLACK 1e-12
#else
#define CLR_TRIANGLE_PLANE_SLACK 9.5367432e-7f /* 2^-20 */
#endif

/* The hit's weights u, v, w (signed volumes, the squares of lengths times a length) and their
 * products with the corners' distances along the ray (cubes) overflow float for a triangle
 * about 1e13 from the ray's origin and underflow near 1e-13; the coordinate and length ranges
 * (docs/scene-format.md, Numeric ranges) reach further. Where their sum det lies outside
 * [2^-60, 2^60] the weights are first scaled by a power of two that brings det near 1: t is a
 * ratio of sums of equal degree, so the scale changes no bit of it, and a det within the
 * bounds keeps every product far inside float's range. Nothing changes for any other det. */
#define CLR_TRIANGLE_SCALED_BELOW 8.6736174e-19f /* 2^-60 */
#define CLR_TRIANGLE_SCALED_ABOVE 1.1529215e18f  /* 2^60 */

real triangle_nearest_t(real3 origin)
{
    return (real)CLR_TRIANGLE_SELF_GAP * (fabs(origin.x) + fabs(origin.y) + fabs(origin.z));
}

real triangle_plane_slack(real3 origin)
{
    return (real)CLR_TRIANGLE_PLANE_SLACK * (fabs(origin.x) + fabs(origin.y) + fabs(origin.z));
}

/* The least t of a hit: none counts (infinity) where the origin lies within the plane's
 * slack (triangle_plane_slack(), times |n.x| + |n.y| + |n.z|) of the plane, from which it is
 * `offset` = (c0 - o).n, else 0. */
real triangle_least_t(real offset, real3 n, real slack)
{
    return fabs(offset) <= slack * (fabs(n.x) + fabs(n.y) + fabs(n.z)) ? INFINITY : 0.0f;
}

/* The plane's normal the host stored in the corners' w (ClrTriangle). */
real3 triangle_plane_normal(__global const ClrTriangle* triangle)
{
    return convert_real3((float3)(triangle->corner0.w, triangle->corner1.w, triangle->corner2.w));
}

/* The shading its mesh gives every one of its triangles (ClrTriangle::mesh_flags). */
__global const ClrMeshSurface* triangle_mesh_surface(int index, CLR_SCENE_PARAMS)
{
    return &mesh_surfaces[triangles[index].mesh_flags >> CLR_TRIANGLE_MESH_SHIFT];
}

/* The origin's offset (c0 - o).n from the plane, with a bound on its rounding (in units of
 * its precision), the more exact of two ways. From the corner as stored (`a` = c0 - o): exact
 * near the triangle, and of the plane that the corners as stored span, where the edge tests
 * decide; but the corner is rounded relative to the eye, so for a triangle 1e8 across the
 * plane was units off near the eye however near it passes. From the plane's offset from the
 * eye, which the host computed in double (ClrTriangle plane_offset), less n.o: exact near the eye
 * (o = 0 for a primary ray), but for a ray leaving a far triangle n.o is as large as the
 * triangle is far. */
typedef struct {
    real offset, error;
} PlaneOffset;

PlaneOffset triangle_offset(__global const ClrTriangle* triangle, real3 a, real3 n, real3 origin)
{
    real stored = (real)triangle->plane_offset;
    PlaneOffset from_corner = {dot3(a, n), abs_dot3(a, n)};
    PlaneOffset from_eye = {stored - dot3(n, origin), fabs(stored) + abs_dot3(n, origin)};
    return from_eye.error < from_corner.error ? from_eye : from_corner;
}

/* Whether the plane's t, offset / facing, is more exact than the blend of the corners'
 * distances along the ray: the blend rounds in proportion to the largest of those distances
 * (`blend_error`, the largest abs_dot3() of a corner and the direction; its weights are convex),
 * the plane's t in proportion to its offset's error plus t times that of `facing` (`slant`,
 * abs_dot3() of the direction and n), over |facing|. A grazing ray keeps the blend, and so
 * does every triangle no larger than its distance from the origin. */
bool plane_t_is_exacter(real offset_error, real t_plane, real slant, real facing, real blend_error)
{
    return offset_error + fabs(t_plane) * slant < blend_error * fabs(facing);
}

/* Whether a ray whose origin is `offset` = (c0 - o).n from the plane and whose direction has
 * `facing` = d.n meets the plane ahead of its origin. */
bool plane_ahead(real offset, real facing)
{
    return (offset > 0.0f && facing > 0.0f) || (offset < 0.0f && facing < 0.0f);
}

/* The triangle's corners relative to `origin`. */
typedef struct {
    real3 a, b, c;
} TriangleCorners;

TriangleCorners triangle_corners(__global const ClrTriangle* triangle, real3 origin)
{
    TriangleCorners corners;
    corners.a = convert_real3(triangle->corner0.xyz) - origin;
    corners.b = convert_real3(triangle->corner1.xyz) - origin;
    corners.c = convert_real3(triangle->corner2.xyz) - origin;
    return corners;
}

/* p x q, written out so that q x p is exactly its negation. */
real3 edge_cross(real3 p, real3 q)
{
    return (real3)(p.y * q.z - p.z * q.y, p.z * q.x - p.x * q.z, p.x * q.y - p.y * q.x);
}

/* X such that d.X is the volume d.((p - o) x (q - o)) of a ray from `origin` and the edge
 * (p, q), for every direction d: (p - o) x (q - p). The same vector mathematically as
 * (p - o) x (q - o), but without its products of the corners' distances from o with each
 * other: for a triangle a thousand times its size away those are a million times its area,
 * and their rounding swamped the volume (a far mesh's silhouette broke into blocks). */
real3 edge_volume_normal(real3 p, real3 q, real3 origin)
{
    return edge_cross(p - origin, q - p);
}

/* d.((p - o) x (q - o)): see edge_volume_normal(). */
real edge_volume(real3 p, real3 q, real3 origin, real3 direction)
{
    return dot3(edge_volume_normal(p, q, origin), direction);
}

/* Distance along the unit direction to the triangle with t_min < t < t_max, or +inf. */
real triangle_distance(__global const ClrTriangle* triangle, real3 origin, real3 direction, real t_max)
{
    TriangleCorners k = triangle_corners(triangle, origin);
    real3 c0 = convert_real3(triangle->corner0.xyz);
    real3 c1 = convert_real3(triangle->corner1.xyz);
    real3 c2 = convert_real3(triangle->corner2.xyz);
    real u = edge_volume(c1, c2, origin, direction); /* weight of corner 0 */
    real v = edge_volume(c2, c0, origin, direction); /* weight of corner 1 */
    real w = edge_volume(c0, c1, origin, direction); /* weight of corner 2 */
    real longest = (real)triangle->longest_edge;
    real det = u + v + w;
    if (!banded_inside(u, v, w, det, edge_band(norm1(k.a) + longest, longest)))
        return INFINITY;
    real3 n = triangle_plane_normal(triangle);
    bool near_eye = (triangle->mesh_flags & CLR_SURFACE_NEAR_EYE) != 0u;
    PlaneOffset plane = near_eye ? triangle_offset(triangle, k.a, n, origin) : (PlaneOffset){dot3(k.a, n), 0.0f};
    real offset = plane.offset, facing = dot3(direction, n);
    if (!plane_ahead(offset, facing))
        return INFINITY;
    if (!(fabs(det) >= CLR_TRIANGLE_SCALED_BELOW && fabs(det) <= CLR_TRIANGLE_SCALED_ABOVE)) {
        real scale = ldexp((real)1.0f, -ilogb(det));
        u *= scale;
        v *= scale;
        w *= scale;
        det *= scale;
    }
    real t = (u * dot3(k.a, direction) + v * dot3(k.b, direction) + w * dot3(k.c, direction)) / det;
    real t_plane = offset / facing;
    if (near_eye) {
        real blend_error = fmax(fmax(abs_dot3(k.a, direction), abs_dot3(k.b, direction)), abs_dot3(k.c, direction));
        if (plane_t_is_exacter(plane.error, t_plane, abs_dot3(direction, n), facing, blend_error))
            t = t_plane;
    }
    real least = triangle_least_t(offset, n, triangle_plane_slack(origin));
    if (!(t > least))
        t = t_plane;
    if (!(t > least && t < t_max))
        return INFINITY;
    real3 p = origin + t * direction;
    if (outside_by_volumes(u, v, w, det) && !within_corner_box(p.x, p.y, p.z, c0, c1, c2))
        return INFINITY;
    return t;
}

/* triangle_distance()'s scaling of the weights of the lanes in `hit` whose det is out of its
 * bounds, lane by lane the same operations. */
CLR_PACKET_INLINE void scale_weights16(mask16 hit, real16* u, real16* v, real16* w, real16* det)
{
    mask16 scaled = hit && !(fabs(*det) >= CLR_TRIANGLE_SCALED_BELOW && fabs(*det) <= CLR_TRIANGLE_SCALED_ABOVE);
    if (!any_lanes16(scaled))
        return;
    real16 scale = select((real16)(1.0f), ldexp((real16)(1.0f), -ilogb(*det)), scaled);
    *u *= scale;
    *v *= scale;
    *w *= scale;
    *det *= scale;
}

/* edge_volume() for 16 directions from one origin. */
CLR_PACKET_INLINE real16 edge_volume16(real3 p, real3 q, real3 origin, Directions16 d)
{
    return dot16(edge_volume_normal(p, q, origin), d);
}

/* edge_volume() for 16 rays from 16 origins, lane by lane the same operations. */
CLR_PACKET_INLINE real16 edge_volume16_from(real3 p, real3 q, Points16 o, Directions16 d)
{
    real3 e = q - p;
    real16 sx = p.x - o.x, sy = p.y - o.y, sz = p.z - o.z;
    /* dot3(edge_cross(p - o, e), d) written out */
    return (sy * e.z - sz * e.y) * d.x + (sz * e.x - sx * e.z) * d.y + (sx * e.y - sy * e.x) * d.z;
}

/* triangle_distance() for 16 rays from one origin (t_max = infinity): the edges' cross
 * products do not depend on the direction, so they are made once for the 16 lanes. */
CLR_PACKET_INLINE real16 triangle_distance16(__global const ClrTriangle* triangle, real3 origin, Directions16 d)
{
    TriangleCorners k = triangle_corners(triangle, origin);
    real3 c0 = convert_real3(triangle->corner0.xyz);
    real3 c1 = convert_real3(triangle->corner1.xyz);
    real3 c2 = convert_real3(triangle->corner2.xyz);
    real16 u = edge_volume16(c1, c2, origin, d);
    real16 v = edge_volume16(c2, c0, origin, d);
    real16 w = edge_volume16(c0, c1, origin, d);
    real longest = (real)triangle->longest_edge;
    real16 det = u + v + w;
    mask16 hit = banded_inside16(u, v, w, det, (real16)(edge_band(norm1(k.a) + longest, longest)));
    if (!any_lanes16(hit))
        return (real16)(INFINITY);
    real3 n = triangle_plane_normal(triangle);
    bool near_eye = (triangle->mesh_flags & CLR_SURFACE_NEAR_EYE) != 0u;
    PlaneOffset plane = near_eye ? triangle_offset(triangle, k.a, n, origin) : (PlaneOffset){dot3(k.a, n), 0.0f};
    real offset = plane.offset;
    real16 facing = dot16(n, d);
    hit = hit && ((offset > 0.0f && facing > 0.0f) || (offset < 0.0f && facing < 0.0f)); /* plane_ahead() */
    scale_weights16(hit, &u, &v, &w, &det);
    real16 t = (u * dot16(k.a, d) + v * dot16(k.b, d) + w * dot16(k.c, d)) / det;
    if (near_eye) {
        real16 t_plane = offset / facing;
        /* plane_t_is_exacter() lane by lane, with abs_dot3() written out */
        real16 blend_error = fmax(fmax(fabs(k.a.x * d.x) + fabs(k.a.y * d.y) + fabs(k.a.z * d.z),
                                       fabs(k.b.x * d.x) + fabs(k.b.y * d.y) + fabs(k.b.z * d.z)),
                                  fabs(k.c.x * d.x) + fabs(k.c.y * d.y) + fabs(k.c.z * d.z));
        real16 slant = fabs(d.x * n.x) + fabs(d.y * n.y) + fabs(d.z * n.z);
        t = select(t, t_plane, hit && plane.error + fabs(t_plane) * slant < blend_error * fabs(facing));
    }
    real nearest = triangle_nearest_t(origin);
    mask16 behind = hit && !(t > nearest);
    if (any_lanes16(behind))
        t = select(t, offset / facing, behind);
    hit = hit && t > nearest;
    mask16 outside = hit && outside_by_volumes16(u, v, w, det);
    if (any_lanes16(outside))
        hit = hit && (!outside ||
                      within_corner_box16(origin.x + t * d.x, origin.y + t * d.y, origin.z + t * d.z, c0, c1, c2));
    return select((real16)(INFINITY), t, hit);
}

/* triangle_distance() for 16 rays from 16 origins (t_max = infinity), the shadow rays of a
 * packet's hit points (packet/shadows16.cl): lane by lane the same operations in the same
 * order, so each lane's t is the one triangle_distance() gives its ray, to the last bit.
 * `slack` is triangle_plane_slack() of each lane's origin. Only the lanes in `tested` are
 * answered (the others get infinity): a lane whose ray leaves this very triangle passes its
 * edge tests, and would otherwise take every packet through the whole test. */
CLR_PACKET_INLINE real16 triangle_distance16_from(__global const ClrTriangle* triangle, Points16 o, real16 slack,
                                                  Directions16 d, mask16 tested)
{
    real3 c0 = convert_real3(triangle->corner0.xyz);
    real3 c1 = convert_real3(triangle->corner1.xyz);
    real3 c2 = convert_real3(triangle->corner2.xyz);
    real16 ax = c0.x - o.x, ay = c0.y - o.y, az = c0.z - o.z;
    real16 bx = c1.x - o.x, by = c1.y - o.y, bz = c1.z - o.z;
    real16 cx = c2.x - o.x, cy = c2.y - o.y, cz = c2.z - o.z;
    real16 u = edge_volume16_from(c1, c2, o, d);
    real16 v = edge_volume16_from(c2, c0, o, d);
    real16 w = edge_volume16_from(c0, c1, o, d);
    /* each lane's reach as triangle_distance() finds it: norm1() of corner 0 from its origin */
    real longest = (real)triangle->longest_edge;
    real16 reach = (fabs(ax) + fabs(ay) + fabs(az)) + longest;
    real16 det = u + v + w;
    mask16 hit = tested && banded_inside16(u, v, w, det, edge_band16(reach, longest));
    if (!any_lanes16(hit))
        return (real16)(INFINITY);
    real3 n = triangle_plane_normal(triangle);
    bool near_eye = (triangle->mesh_flags & CLR_SURFACE_NEAR_EYE) != 0u;
    real16 offset = ax * n.x + ay * n.y + az * n.z, offset_error = (real16)(0.0f);
    if (near_eye) { /* triangle_offset() lane by lane */
        real stored = (real)triangle->plane_offset;
        offset_error = fabs(ax * n.x) + fabs(ay * n.y) + fabs(az * n.z);
        real16 from_eye = stored - (n.x * o.x + n.y * o.y + n.z * o.z);
        real16 from_eye_error = fabs(stored) + (fabs(n.x * o.x) + fabs(n.y * o.y) + fabs(n.z * o.z));
        mask16 eye_exacter = from_eye_error < offset_error;
        offset = select(offset, from_eye, eye_exacter);
        offset_error = select(offset_error, from_eye_error, eye_exacter);
    }
    real16 facing = d.x * n.x + d.y * n.y + d.z * n.z;
    hit = hit && ((offset > 0.0f && facing > 0.0f) || (offset < 0.0f && facing < 0.0f)); /* plane_ahead() */
    scale_weights16(hit, &u, &v, &w, &det);
    real16 t = (u * (ax * d.x + ay * d.y + az * d.z) + v * (bx * d.x + by * d.y + bz * d.z) +
                w * (cx * d.x + cy * d.y + cz * d.z)) /
               det;
    if (near_eye) {
        real16 t_plane = offset / facing;
        /* plane_t_is_exacter() lane by lane, with abs_dot3() written out */
        real16 blend_error = fmax(fmax(fabs(ax * d.x) + fabs(ay * d.y) + fabs(az * d.z),
                                       fabs(bx * d.x) + fabs(by * d.y) + fabs(bz * d.z)),
                                  fabs(cx * d.x) + fabs(cy * d.y) + fabs(cz * d.z));
        real16 slant = fabs(d.x * n.x) + fabs(d.y * n.y) + fabs(d.z * n.z);
        t = select(t, t_plane, hit && offset_error + fabs(t_plane) * slant < blend_error * fabs(facing));
    }
    /* triangle_least_t() lane by lane */
    real16 least = select((real16)(0.0f), (real16)(INFINITY), fabs(offset) <= slack * (fabs(n.x) + fabs(n.y) + fabs(n.z)));
    mask16 behind = hit && !(t > least);
    if (any_lanes16(behind))
        t = select(t, offset / facing, behind);
    hit = hit && t > least;
    mask16 outside = hit && outside_by_volumes16(u, v, w, det);
    if (any_lanes16(outside))
        hit = hit && (!outside || within_corner_box16(o.x + t * d.x, o.y + t * d.y, o.z + t * d.z,
                                                      c0, c1, c2));
    return select((real16)(INFINITY), t, hit);
}

/* The kind's functions for kinds/kinds.cl. */

real triangle_hit_distance(int index, real3 origin, real3 direction, real t_max, CLR_SCENE_PARAMS)
{
    return triangle_distance(&triangles[index], origin, direction, t_max);
}

/* triangle_hit_distance() for 16 primary rays; a triangle shows no texels. */
CLR_PACKET_INLINE real16 triangle_hit_distance16(int index, real3 origin, Directions16 d, int want_texels,
                                                 uint16* texel, CLR_SCENE_PARAMS)
{
    return triangle_distance16(&triangles[index], origin, d);
}

/* A triangle's geometric normal n = e1 x e2 (its edges from corner 0), n.n, and where
 * `weights`, the barycentric weights b1, b2 of the point p - c0 = b1 e1 + b2 e2:
 * b1 = ((p - c0) x e2).n / n.n, b2 = (e1 x (p - c0)).n / n.n. */
typedef struct {
    real3 geometric;
    real area2, b1, b2;
} TriangleFrame;

TriangleFrame triangle_frame(real3 e1, real3 e2, real3 p, bool weights)
{
    TriangleFrame frame;
    frame.geometric = edge_cross(e1, e2);
    frame.area2 = dot3(frame.geometric, frame.geometric);
    frame.b1 = frame.b2 = 0.0f;
    if (weights) {
        frame.b1 = dot3(edge_cross(p, e2), frame.geometric) / frame.area2;
        frame.b2 = dot3(edge_cross(e1, p), frame.geometric) / frame.area2;
    }
    return frame;
}

/* The unit normal at `point`, turned to face the ray that arrives along `direction` (a mesh
 * has no back): the corner normals interpolated with the point's barycentric coordinates
 * where the mesh gives them, else the geometric normal. */
real3 triangle_normal(int index, real3 point, real3 direction, CLR_SCENE_PARAMS)
{
    __global const ClrTriangle* triangle = &triangles[index];
    real3 c0 = convert_real3(triangle->corner0.xyz);
    real3 e1 = convert_real3(triangle->corner1.xyz) - c0;
    real3 e2 = convert_real3(triangle->corner2.xyz) - c0;
    real3 p = point - c0;
    bool weights = triangle->normals >= 0;
    TriangleFrame frame = triangle_frame(e1, e2, p, weights);
    /* n.n is an edge to the fourth power, which overflows float for edges beyond about 4e9 and
     * underflows below about 1e-10 (and a weight's numerator may overflow for a long sliver).
     * Where n.n leaves [2^-100, 2^100] or a weight is not finite, the frame is made again from
     * the edges and p scaled by a power of two that brings the longest edge near 1: each of its
     * values is a ratio of products of equal degree, so the scale changes no bit of what did
     * not overflow, and any other triangle keeps the first frame. */
    if (!(frame.area2 >= 7.8886091e-31f && frame.area2 <= 1.2676506e30f) || !isfinite(frame.b1) ||
        !isfinite(frame.b2)) {
        real size = fmax(fmax(fmax(fabs(e1.x), fabs(e1.y)), fmax(fabs(e1.z), fabs(e2.x))), fmax(fabs(e2.y), fabs(e2.z)));
        real scale = ldexp((real)1.0f, -ilogb(size));
        frame = triangle_frame(e1 * scale, e2 * scale, p * scale, weights);
    }
    real3 normal = frame.geometric;
    if (weights) {
        real b0 = 1.0f - frame.b1 - frame.b2;
        __global const float4* n = &triangle_normals[triangle->normals];
        real3 blended =
            b0 * convert_real3(n[0].xyz) + frame.b1 * convert_real3(n[1].xyz) + frame.b2 * convert_real3(n[2].xyz);
        if (dot3(blended, blended) > 0.0f)
            normal = blended;
    }
    normal = unit3(normal);
    return dot3(normal, direction) > 0.0f ? -normal : normal;
}

/* Corners and corner normals of the triangles of 16 lanes, each lane's as the float4s they are
 * stored as, in private arrays: what triangle_normals16() gathers before computing in vectors
 * (columns16()). A lane's six float4s are six loads and six stores; stored as 19 floats (x, y
 * and z apart) they were 19 stores a lane (docs/benchmarks.md, Shadow packets' own triangles). */
typedef struct {
    float4 c0[16], c1[16], c2[16], n0[16], n1[16], n2[16];
    int weighted[16];
} TriangleLanes16;

/* Lane `lane`'s triangle `index` into `lanes`, read as triangle_normal() reads it; a lane
 * outside the packet's triangles (index < 0) gets a unit right triangle without corner
 * normals, whose values are finite and ignored. */
CLR_PACKET_INLINE void gather_triangle16(TriangleLanes16* lanes, int lane, int index, CLR_SCENE_PARAMS)
{
    float4 c0 = (float4)(0.0f), c1 = (float4)(1.0f, 0.0f, 0.0f, 0.0f), c2 = (float4)(0.0f, 1.0f, 0.0f, 0.0f);
    float4 n0 = (float4)(0.0f), n1 = (float4)(0.0f), n2 = (float4)(0.0f);
    int weighted = 0;
    if (index >= 0) {
        __global const ClrTriangle* triangle = &triangles[index];
        c0 = triangle->corner0;
        c1 = triangle->corner1;
        c2 = triangle->corner2;
        weighted = triangle->normals >= 0;
        if (weighted) {
            __global const float4* n = &triangle_normals[triangle->normals];
            n0 = n[0];
            n1 = n[1];
            n2 = n[2];
        }
    }
    lanes->c0[lane] = c0, lanes->c1[lane] = c1, lanes->c2[lane] = c2;
    lanes->n0[lane] = n0, lanes->n1[lane] = n1, lanes->n2[lane] = n2;
    lanes->weighted[lane] = weighted;
}

/* The x, y and z of 16 lanes' float4s (lane l's at rows[l]), as vectors: four vector loads
 * and permutes. */
CLR_PACKET_INLINE void float_columns16(const float4* rows, float16* x, float16* y, float16* z)
{
    const float* f = (const float*)rows;
    float16 q0 = vload16(0, f), q1 = vload16(1, f), q2 = vload16(2, f), q3 = vload16(3, f);
    *x = (float16)(q0.s048c, q1.s048c, q2.s048c, q3.s048c);
    *y = (float16)(q0.s159d, q1.s159d, q2.s159d, q3.s159d);
    *z = (float16)(q0.s26ae, q1.s26ae, q2.s26ae, q3.s26ae);
}

/* float_columns16() in `real`. */
CLR_PACKET_INLINE void columns16(const float4* rows, real16* x, real16* y, real16* z)
{
    float16 fx, fy, fz;
    float_columns16(rows, &fx, &fy, &fz);
    *x = convert_real16(fx);
    *y = convert_real16(fy);
    *z = convert_real16(fz);
}

/* triangle_normal() of 16 lanes, lane l on triangle indices[l] (or none, where negative) at
 * point p[l] met along d[l]: lane by lane the same operations in the same order, so each
 * lane's normal is triangle_normal()'s to the last bit. A lane whose frame needs
 * triangle_normal()'s rescaling (a triangle near float's range) is handed to it. Lit meshes
 * spent about a quarter of their kernel time finding normals one lane at a time. */
CLR_PACKET_INLINE Directions16 triangle_normals16(const int* indices, Points16 p, Directions16 d, CLR_SCENE_PARAMS)
{
    TriangleLanes16 t;
    for (int lane = 0; lane < 16; ++lane)
        gather_triangle16(&t, lane, indices[lane], CLR_SCENE_ARGS);
    real16 c0x, c0y, c0z, c1x, c1y, c1z, c2x, c2y, c2z;
    columns16(t.c0, &c0x, &c0y, &c0z);
    columns16(t.c1, &c1x, &c1y, &c1z);
    columns16(t.c2, &c2x, &c2y, &c2z);
    real16 e1x = c1x - c0x, e1y = c1y - c0y, e1z = c1z - c0z; /* the edges as triangle_normal() makes them */
    real16 e2x = c2x - c0x, e2y = c2y - c0y, e2z = c2z - c0z;
    real16 px = p.x - c0x, py = p.y - c0y, pz = p.z - c0z;
    /* triangle_frame(): geometric = edge_cross(e1, e2), area2, b1, b2 */
    real16 gx = e1y * e2z - e1z * e2y, gy = e1z * e2x - e1x * e2z, gz = e1x * e2y - e1y * e2x;
    real16 area2 = gx * gx + gy * gy + gz * gz;
    mask16 weighted = convert_mask16(vload16(0, t.weighted) != (int16)(0));
    real16 b1 = ((py * e2z - pz * e2y) * gx + (pz * e2x - px * e2z) * gy + (px * e2y - py * e2x) * gz) / area2;
    real16 b2 = ((e1y * pz - e1z * py) * gx + (e1z * px - e1x * pz) * gy + (e1x * py - e1y * px) * gz) / area2;
    b1 = select((real16)(0.0f), b1, weighted);
    b2 = select((real16)(0.0f), b2, weighted);
    real16 b0 = 1.0f - b1 - b2;
    real16 n0x, n0y, n0z, n1x, n1y, n1z, n2x, n2y, n2z;
    columns16(t.n0, &n0x, &n0y, &n0z);
    columns16(t.n1, &n1x, &n1y, &n1z);
    columns16(t.n2, &n2x, &n2y, &n2z);
    real16 bx = b0 * n0x + b1 * n1x + b2 * n2x;
    real16 by = b0 * n0y + b1 * n1y + b2 * n2y;
    real16 bz = b0 * n0z + b1 * n1z + b2 * n2z;
    mask16 blend = weighted && (bx * bx + by * by + bz * bz) > 0.0f;
    real16 nx = select(gx, bx, blend), ny = select(gy, by, blend), nz = select(gz, bz, blend);
    real16 length = sqrt(nx * nx + ny * ny + nz * nz); /* unit3() */
    nx = nx / length;
    ny = ny / length;
    nz = nz / length;
    mask16 away = (nx * d.x + ny * d.y + nz * d.z) > 0.0f;
    Directions16 normal;
    normal.x = select(nx, -nx, away);
    normal.y = select(ny, -ny, away);
    normal.z = select(nz, -nz, away);
    mask16 rescaled = !(area2 >= 7.8886091e-31f && area2 <= 1.2676506e30f) || !isfinite(b1) || !isfinite(b2);
    if (any_lanes16(rescaled)) {
        real x[16], y[16], z[16], ox[16], oy[16], oz[16], dx[16], dy[16], dz[16];
        int again[16];
        vstore16(normal.x, 0, x);
        vstore16(normal.y, 0, y);
        vstore16(normal.z, 0, z);
        vstore16(p.x, 0, ox);
        vstore16(p.y, 0, oy);
        vstore16(p.z, 0, oz);
        vstore16(d.x, 0, dx);
        vstore16(d.y, 0, dy);
        vstore16(d.z, 0, dz);
        vstore16(convert_int16(rescaled), 0, again);
        for (int lane = 0; lane < 16; ++lane) {
            if (indices[lane] < 0 || !again[lane])
                continue;
            real3 n = triangle_normal(indices[lane], (real3)(ox[lane], oy[lane], oz[lane]),
                                      (real3)(dx[lane], dy[lane], dz[lane]), CLR_SCENE_ARGS);
            x[lane] = n.x, y[lane] = n.y, z[lane] = n.z;
        }
        normal.x = vload16(0, x);
        normal.y = vload16(0, y);
        normal.z = vload16(0, z);
    }
    return normal;
}

uint triangle_flags(int index, CLR_SCENE_PARAMS)
{
    uint word = triangles[index].mesh_flags; /* its own flags and its mesh, read once */
    return (word & CLR_TRIANGLE_OWN_FLAGS) | mesh_surfaces[word >> CLR_TRIANGLE_MESH_SHIFT].flags;
}

/* Its Blinn-Phong material (ClrMaterial) in `materials`. */
uint triangle_material(int index, CLR_SCENE_PARAMS)
{
    return triangle_mesh_surface(index, CLR_SCENE_ARGS)->material;
}

/* The colour before lighting: the mesh's ambient colour. */
float3 triangle_surface_color(int index, real3 origin, real3 direction, real t, CLR_SCENE_PARAMS)
{
    return triangle_mesh_surface(index, CLR_SCENE_ARGS)->color.xyz;
}

CLR_PACKET_INLINE Colors16 triangle_flat_colors16(int index, uint16 texel, CLR_SCENE_PARAMS)
{
    return uniform_colors16(triangle_mesh_surface(index, CLR_SCENE_ARGS)->color.xyz);
}

/* Meshes are lit by the sun as spheres are (docs/scene-format.md, Meshes). */
bool triangle_is_lit(void)
{
    return true;
}

CLR_PACKET_INLINE void triangle_prefetch(int index, CLR_SCENE_PARAMS)
{
}

#if CLR_FEATURE_TRIANGLE_TIES
/* The triangle a hit at `point`, distance t along its ray, on triangle `index` is shaded as
 * (docs/scene-format.md, Meshes, "Shared edges and vertices"): for a point within t 2^-20
 * (|.|_1) of a corner, the lowest triangle of its mesh placement around that corner; else for
 * one within that band of an edge line (|(P - a) x e|_1 <= band |e|_1), the lowest along that
 * edge; else `index`. `*other` receives the lowest triangle there other than `index` (`index`
 * where there is none), which secondary rays leave too. So a ray through a shared ridge is
 * shaded alike whichever side its rounding took, here and in the reference
 * (reference/shade.cpp, settled(), with the same neighbours: host/scene/triangle_ties.h).
 * `triangle_ties` holds six a triangle: the lowest other along the edges opposite corners 0, 1,
 * 2, then around corners 0, 1, 2. The band is 16 float ulps of t: 2^-16 was wider than a pixel
 * under narrow lenses (fov 0.05 deg: about 3 pixels each side of every edge). */
int triangle_settled_index(int index, real3 point, real t, int* other, CLR_SCENE_PARAMS)
{
    __global const ClrTriangle* triangle = &triangles[index];
    real3 c[3];
    c[0] = convert_real3(triangle->corner0.xyz);
    c[1] = convert_real3(triangle->corner1.xyz);
    c[2] = convert_real3(triangle->corner2.xyz);
    real band = t * (real)(1.0f / 1048576.0f); /* 2^-20 */
    *other = index;
    int3 around = vload3(2 * index + 1, triangle_ties);
    int corners_other[3] = {around.x, around.y, around.z};
    for (int k = 0; k < 3; ++k) {
        real3 p = point - c[k];
        if (fabs(p.x) + fabs(p.y) + fabs(p.z) <= band) {
            *other = corners_other[k];
            return min(index, *other);
        }
    }
    int3 along = vload3(2 * index, triangle_ties);
    int edges_other[3] = {along.x, along.y, along.z};
    for (int k = 0; k < 3; ++k) {
        real3 a = c[(k + 1) % 3];
        real3 e = c[(k + 2) % 3] - a;
        real3 p = point - a;
        real3 x = (real3)(p.y * e.z - p.z * e.y, p.z * e.x - p.x * e.z, p.x * e.y - p.y * e.x);
        if (fabs(x.x) + fabs(x.y) + fabs(x.z) <= band * (fabs(e.x) + fabs(e.y) + fabs(e.z))) {
            *other = edges_other[k];
            return min(index, *other);
        }
    }
    return index;
}
#endif

#endif /* CLR_KINDS_TRIANGLE_CL */
