/* Which side of a triangle's edges a ray passes (docs/scene-format.md, Meshes, "No cracks" and
 * "Edges and the band"). kinds/triangle.cl computes each edge's side as a signed volume of the
 * ray and the edge, one rounding per edge; near zero those roundings, each edge's on its own,
 * and the float corners' and directions' own rounding, decide on which side of an edge a ray
 * exactly through it falls, differently in float, in double and in the reference. So every
 * volume within a band of zero counts as zero: the ray passes through that edge, in every
 * kernel and in the reference alike.
 *
 * The band is a rule, not a rounding: the same share of the ray's reach whatever `real` is.
 * The volume rounds in float by at most 7.1 M L roundings (M: corner 0's norm1() from the
 * ray's origin plus the longest edge, L: the longest edge), and the float corners and
 * direction, rounded from the host's doubles, move it by a few more; the band is
 * 2^-19 M (L + 2^-22 M), 32 roundings. A volume farther than the band from zero therefore has
 * the exact one's sign, and two triangles never both refuse a ray through their shared edge or
 * vertex: the one whose volume of the edge rounds to outside sees it beyond the band, the
 * other within it or inside. Around a triangle's longest edge, on a 1920-pixel-wide image at
 * 45 degrees, the band is about 1/220 of a pixel wide; it widens silhouettes and shadows by
 * that much (the lit mesh rows of the benchmark differ from Embree's image in 0.003% of their
 * pixels, docs/benchmarks.md). */
#ifndef CLR_KINDS_TRIANGLE_SIDES_CL
#define CLR_KINDS_TRIANGLE_SIDES_CL

#include "common/math.cl"
#include "packet/lane_masks.cl"
#include "packet/packet_types.cl"

#define CLR_EDGE_BAND 1.9073486e-6f       /* 2^-19 */
#define CLR_EDGE_BAND_REACH 2.3841858e-7f /* 2^-22 */

/* |x| + |y| + |z|. */
real norm1(real3 v)
{
    return fabs(v.x) + fabs(v.y) + fabs(v.z);
}

/* The band of a triangle's edge volumes for a ray whose reach is `reach` (M above), the
 * triangle's longest edge `longest` (ClrTriangle::longest_edge); the direction is a unit vector. */
real edge_band(real reach, real longest)
{
    return (real)CLR_EDGE_BAND * reach * (longest + (real)CLR_EDGE_BAND_REACH * reach);
}

/* edge_band() of 16 lanes' reaches. */
CLR_PACKET_INLINE real16 edge_band16(real16 reach, real longest)
{
    return (real)CLR_EDGE_BAND * reach * (longest + (real)CLR_EDGE_BAND_REACH * reach);
}

/* Whether the ray passes inside the triangle whose edge volumes are u, v, w (det their sum):
 * each volume is of one sign or within the band of zero, and their sum, the triangle's area as
 * seen along the ray, is beyond the band on that sign. A triangle seen within the band of edge
 * on is not met, however its volumes round. */
bool banded_inside(real u, real v, real w, real det, real band)
{
    return (u >= -band && v >= -band && w >= -band && det > band) ||
           (u <= band && v <= band && w <= band && det < -band);
}

/* banded_inside() for 16 lanes. */
CLR_PACKET_INLINE mask16 banded_inside16(real16 u, real16 v, real16 w, real16 det, real16 band)
{
    return (u >= -band && v >= -band && w >= -band && det > band) ||
           (u <= band && v <= band && w <= band && det < -band);
}

/* A hit that the band alone admits (the ray outside the triangle as its volumes are) counts only
 * where its point lies within the box of the triangle's corners, widened by this share of their
 * largest coordinate (all relative to the eye). The band admits points outside that box near a
 * corner, or outside an edge along an axis, which the boxes the ray is tested against first (the
 * BVH's nodes, the reference's tree: 1e-6 of their largest coordinate) would refuse, so that
 * one path of the kernels or the reference would see the hit and another not. 2^-21 is half
 * their room, and four float steps of a point's coordinates. */
#define CLR_EDGE_BAND_BOX 4.7683716e-7f /* 2^-21 */

/* Whether the ray passes outside the triangle as its edge volumes are (one of another sign than
 * their sum det), inside only by the band. */
bool outside_by_volumes(real u, real v, real w, real det)
{
    return det > 0.0f ? fmin(fmin(u, v), w) < 0.0f : fmax(fmax(u, v), w) > 0.0f;
}

/* outside_by_volumes() for 16 lanes. */
CLR_PACKET_INLINE mask16 outside_by_volumes16(real16 u, real16 v, real16 w, real16 det)
{
    return (det > 0.0f && fmin(fmin(u, v), w) < 0.0f) || (det < 0.0f && fmax(fmax(u, v), w) > 0.0f);
}

/* The widening of the box of corners c0, c1, c2 (relative to the eye): CLR_EDGE_BAND_BOX of
 * their largest coordinate. */
real corner_box_room(real3 lower, real3 upper)
{
    real3 largest = fmax(fabs(lower), fabs(upper));
    return (real)CLR_EDGE_BAND_BOX * fmax(fmax(largest.x, largest.y), largest.z);
}

/* Whether point (x, y, z) relative to the eye lies within the widened box of c0, c1, c2. */
bool within_corner_box(real x, real y, real z, real3 c0, real3 c1, real3 c2)
{
    real3 lower = fmin(fmin(c0, c1), c2), upper = fmax(fmax(c0, c1), c2);
    real room = corner_box_room(lower, upper);
    return x >= lower.x - room && x <= upper.x + room && y >= lower.y - room && y <= upper.y + room &&
           z >= lower.z - room && z <= upper.z + room;
}

/* within_corner_box() for 16 lanes' points. */
CLR_PACKET_INLINE mask16 within_corner_box16(real16 x, real16 y, real16 z, real3 c0, real3 c1, real3 c2)
{
    real3 lower = fmin(fmin(c0, c1), c2), upper = fmax(fmax(c0, c1), c2);
    real room = corner_box_room(lower, upper);
    return x >= lower.x - room && x <= upper.x + room && y >= lower.y - room && y <= upper.y + room &&
           z >= lower.z - room && z <= upper.z + room;
}

#endif /* CLR_KINDS_TRIANGLE_SIDES_CL */
