/* Which side of a triangle's edges a ray passes, decided exactly, so that a ray through a
 * vertex or an edge that triangles share is inside one of them (docs/scene-format.md,
 * Meshes, "No cracks"). kinds/triangle.cl computes each edge's side as a signed volume, fast and one
 * rounding per edge; near zero those roundings, each edge's on its own, could leave a ray
 * through a shared vertex outside every triangle around it. Where a volume is too near zero
 * for its sign to be sure, the side comes from here.
 *
 * The exact test is Woop, Benthin and Wald's (2013), with the shear replaced by two unit vectors
 * across the ray (Duff et al. 2017): each corner, relative to the ray's origin, becomes a point
 * of the plane across the ray, computed once per corner by the same operations whichever
 * triangle asks, and each edge's side is the sign of the 2D orientation of its two points,
 * exact for those points (edge_orientation()). The signs then describe one arrangement of points
 * around the ray, in which a ray inside the fan of triangles around a vertex is inside one of
 * them. */
#ifndef CLR_KINDS_TRIANGLE_SIDES_CL
#define CLR_KINDS_TRIANGLE_SIDES_CL

#include "common/math.cl"
#include "packet/lane_masks.cl"
#include "packet/packet_types.cl"

/* The unit rounding of `real`. */
#if CLR_FEATURE_DOUBLE
#define CLR_REAL_ROUNDING 1.1102230246251565e-16 /* 2^-53 */
#else
#define CLR_REAL_ROUNDING 5.9604645e-8f /* 2^-24 */
#endif

/* Two unit vectors across a unit direction d, with across1 x across2 = d (within 3 roundings
 * per coordinate, measured over 100,000 directions), from Duff et al.'s branchless basis. */
typedef struct {
    real3 across1, across2;
} RayAcross;

RayAcross ray_across(real3 d)
{
    real sign = copysign((real)1.0f, d.z);
    real a = -1.0f / (sign + d.z);
    real b = d.x * d.y * a;
    RayAcross across;
    across.across1 = (real3)(1.0f + sign * (d.x * d.x) * a, sign * b, -sign * d.x);
    across.across2 = (real3)(b, sign + (d.y * d.y) * a, -d.y);
    return across;
}

/* A corner, relative to the ray's origin, as a point of the plane across the ray. */
real2 across_ray(real3 corner, RayAcross across)
{
    return (real2)(dot3(corner, across.across1), dot3(corner, across.across2));
}

/* p.x q.y - p.y q.x with its sign exact: the two products rounded each on its own keep their
 * order, so a difference that is not zero has the right sign; where it is zero, Kahan's
 * difference of products, whose two fused multiply-adds give each product's rounding exactly,
 * decides. q, p gives exactly the negation. */
real edge_orientation(real2 p, real2 q)
{
    real difference = p.x * q.y - p.y * q.x;
    if (difference != 0.0f)
        return difference;
    real product = p.y * q.x;
    return fma(p.x, q.y, -product) + fma(-p.y, q.x, product);
}

/* Whether the ray from the origin along d passes inside the triangle whose corners, relative
 * to that origin, are a, b, c: the three edges' orientations have one sign, or are zero where
 * the ray passes through an edge or a corner. A triangle seen edge on (all three zero) is not
 * met. */
bool triangle_exactly_inside(real3 a, real3 b, real3 c, real3 d)
{
    RayAcross across = ray_across(d);
    real2 pa = across_ray(a, across), pb = across_ray(b, across), pc = across_ray(c, across);
    real u = edge_orientation(pb, pc), v = edge_orientation(pc, pa), w = edge_orientation(pa, pb);
    bool one_sign = (u >= 0.0f && v >= 0.0f && w >= 0.0f) || (u <= 0.0f && v <= 0.0f && w <= 0.0f);
    return one_sign && !(u == 0.0f && v == 0.0f && w == 0.0f);
}

/* |x| + |y| + |z|. */
real norm1(real3 v)
{
    return fabs(v.x) + fabs(v.y) + fabs(v.z);
}

/* Where an edge volume (kinds/triangle.cl) is farther from zero than this, its sign is the
 * exact test's. `reach` bounds the corners' norm1() relative to the ray's origin (M: corner 0's
 * plus the longest edge), `longest` the edges' (L, ClrTriangle::longest_edge); the direction is
 * a unit vector. In units of the rounding: the volume rounds by at most 7.1 M L; the exact
 * test's points across the ray by 4.1 M each, which moves an orientation by at most
 * 11.4 M L + 124 M^2 roundings squared where the ray passes within the triangle (where it does
 * not, a sure sign of another edge says so); across1 x across2 differs from d by 3 roundings,
 * 4 M L. 32 M (L + 4 M) covers their sum. */
real edge_volume_bound(real reach, real longest)
{
    return (32.0f * CLR_REAL_ROUNDING) * reach * (longest + (4.0f * CLR_REAL_ROUNDING) * reach);
}

/* edge_volume_bound() of 16 lanes' reaches. */
CLR_PACKET_INLINE real16 edge_volume_bound16(real16 reach, real longest)
{
    return (32.0f * CLR_REAL_ROUNDING) * reach * (longest + (4.0f * CLR_REAL_ROUNDING) * reach);
}

/* How edge volumes u, v, w that round by up to `bound` place the ray: `maybe` where it may pass
 * inside (no volume is surely of the other sign than another), `inside` where the volumes as
 * they are put it inside (one sign). A ray that may pass inside but is not inside as the volumes
 * are is asked triangle_exactly_inside(); one that is inside as they are is taken, whatever the
 * exact test would say: then it is inside this triangle or, by rounding, its neighbour, and
 * either hit closes the gap. */
typedef struct {
    bool maybe, inside;
} EdgeSides;

EdgeSides edge_sides(real u, real v, real w, real bound)
{
    real least = fmin(fmin(u, v), w), most = fmax(fmax(u, v), w);
    EdgeSides sides = {least >= -bound || most <= bound, least >= 0.0f || most <= 0.0f};
    return sides;
}

/* edge_sides() for 16 lanes. */
typedef struct {
    mask16 maybe, inside;
} EdgeSides16;

CLR_PACKET_INLINE EdgeSides16 edge_sides16(real16 u, real16 v, real16 w, real16 bound)
{
    real16 least = fmin(fmin(u, v), w), most = fmax(fmax(u, v), w);
    EdgeSides16 sides = {least >= -bound || most <= bound, least >= 0.0f || most <= 0.0f};
    return sides;
}

/* edge_orientation() for 16 lanes, lane by lane the same operations. */
CLR_PACKET_INLINE real16 edge_orientation16(real16 px, real16 py, real16 qx, real16 qy)
{
    real16 difference = px * qy - py * qx;
    mask16 zero = difference == 0.0f;
    if (!any_lanes16(zero))
        return difference;
    real16 product = py * qx;
    return select(difference, fma(px, qy, -product) + fma(-py, qx, product), zero);
}

/* triangle_exactly_inside() for 16 lanes, corners a, b, c relative to each lane's origin:
 * lane by lane the same operations, so each lane's answer is the scalar test's. */
CLR_PACKET_INLINE mask16 exactly_inside16(Points16 a, Points16 b, Points16 c, Directions16 d)
{
    /* ray_across() */
    real16 sign = copysign((real16)(1.0f), d.z);
    real16 s = -1.0f / (sign + d.z);
    real16 t = d.x * d.y * s;
    real16 x1 = 1.0f + sign * (d.x * d.x) * s, y1 = sign * t, z1 = -sign * d.x;
    real16 x2 = t, y2 = sign + (d.y * d.y) * s, z2 = -d.y;
    /* across_ray() of the three corners */
    real16 pax = a.x * x1 + a.y * y1 + a.z * z1, pay = a.x * x2 + a.y * y2 + a.z * z2;
    real16 pbx = b.x * x1 + b.y * y1 + b.z * z1, pby = b.x * x2 + b.y * y2 + b.z * z2;
    real16 pcx = c.x * x1 + c.y * y1 + c.z * z1, pcy = c.x * x2 + c.y * y2 + c.z * z2;
    real16 u = edge_orientation16(pbx, pby, pcx, pcy);
    real16 v = edge_orientation16(pcx, pcy, pax, pay);
    real16 w = edge_orientation16(pax, pay, pbx, pby);
    mask16 one_sign = (u >= 0.0f && v >= 0.0f && w >= 0.0f) || (u <= 0.0f && v <= 0.0f && w <= 0.0f);
    return one_sign && !(u == 0.0f && v == 0.0f && w == 0.0f);
}

#endif /* CLR_KINDS_TRIANGLE_SIDES_CL */
