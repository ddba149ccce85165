/* Which of two hits a ray keeps: the nearer, or, as near, the one first in the order
 * spheres, then billboards, by index (the brute-force loop's visiting order; see
 * intersect_scene()). Comparing hits by (t, kind, index) makes any visiting order (BVH,
 * screen tiles, 16 rays at a time) find the brute-force answer, ties included. The scalar
 * rule and its 16-lane form stand side by side so that they stay one rule. */
#ifndef CLR_COMMON_HIT_ORDER_CL
#define CLR_COMMON_HIT_ORDER_CL

#include "common/math.cl"
#include "shared/clr_types.h"

/* Whether a hit at distance t on surface (kind, index) beats `best`. */
bool hit_beats(real t, int kind, int index, Hit best)
{
    if (t != best.t)
        return t < best.t;
    return t < INFINITY && (kind < best.kind || (kind == best.kind && index < best.index));
}

/* hit_beats() for 16 rays at once: surface (kind, index) hit at distances t against each
 * lane's best hit (best_t, best_kind, best_index). Inlined into the packet loop, whose
 * vectors would otherwise pass through the stack. */
__attribute__((always_inline)) mask16 hits_beat16(real16 t, int kind, int index, real16 best_t, int16 best_kind,
                                                   int16 best_index)
{
    int16 order_first = kind < best_kind || (kind == best_kind && index < best_index);
    return t < best_t || (t == best_t && t < INFINITY && convert_real16(order_first) != 0.0f);
}

#endif /* CLR_COMMON_HIT_ORDER_CL */
