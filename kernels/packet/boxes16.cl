/* A BVH node's box against 16 rays at once, for the walks that take a packet through the BVH
 * together (packet/shadows16.cl, packet/bvh_walk16.cl): box_reachable()'s slab test with the
 * same operations lane by lane (a vector rounds as the scalar test would, and the boxes are
 * padded far beyond any rounding, intersect.cl). */
#ifndef CLR_PACKET_BOXES16_CL
#define CLR_PACKET_BOXES16_CL

#include "common/math.cl"
#include "packet/packet_types.cl"
#include "shared/clr_types.h"

/* The larger and the smaller lane by lane, of numbers that are not NaN (as larger()). */
CLR_PACKET_INLINE real16 larger16(real16 a, real16 b) { return select(b, a, a > b); }
CLR_PACKET_INLINE real16 smaller16(real16 a, real16 b) { return select(b, a, a < b); }

/* safe_inverse() lane by lane: no 0 * inf, so no NaN in the slab test. */
CLR_PACKET_INLINE Directions16 safe_inverse16(Directions16 d)
{
    const real16 tiny = (real16)(1e-30f);
    Directions16 inverse;
    inverse.x = (real16)(1.0f) / select(d.x, copysign(tiny, d.x), fabs(d.x) < tiny);
    inverse.y = (real16)(1.0f) / select(d.y, copysign(tiny, d.y), fabs(d.y) < tiny);
    inverse.z = (real16)(1.0f) / select(d.z, copysign(tiny, d.z), fabs(d.z) < tiny);
    return inverse;
}

/* The lanes whose rays from `o` (inverse directions `inverse`) meet `node`'s box no farther
 * than their `t_max`: box_reachable() lane by lane. */
CLR_PACKET_INLINE mask16 box_reached16(__global const ClrBvhNode* node, Points16 o, Directions16 inverse,
                                       real16 t_max)
{
    real16 t0x = ((real16)((real)node->lower.x) - o.x) * inverse.x, t1x = ((real16)((real)node->upper.x) - o.x) * inverse.x;
    real16 t0y = ((real16)((real)node->lower.y) - o.y) * inverse.y, t1y = ((real16)((real)node->upper.y) - o.y) * inverse.y;
    real16 t0z = ((real16)((real)node->lower.z) - o.z) * inverse.z, t1z = ((real16)((real)node->upper.z) - o.z) * inverse.z;
    real16 enter = larger16(larger16(smaller16(t0x, t1x), smaller16(t0y, t1y)), larger16(smaller16(t0z, t1z), (real16)(0.0f)));
    real16 leave = smaller16(smaller16(larger16(t0x, t1x), larger16(t0y, t1y)), larger16(t0z, t1z)) * (real)1.000001f;
    return (enter <= leave) & (enter <= t_max);
}

#endif /* CLR_PACKET_BOXES16_CL */
