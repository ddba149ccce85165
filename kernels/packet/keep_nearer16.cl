/* One object against a packet's 16 primary rays: the step that both ways of finding their
 * nearest hits repeat for each object they reach, the screen tile's list (intersect_packet.cl)
 * and the BVH (packet/bvh_walk16.cl). */
#ifndef CLR_PACKET_KEEP_NEARER16_CL
#define CLR_PACKET_KEEP_NEARER16_CL

#include "common/hit_order.cl"
#include "common/scene_params.cl"
#include "kinds/kinds.cl"
#include "packet/packet_types.cl"
#include "packet/shading_modes.cl"
#include "packet/texels16.cl"
#include "shared/clr_types.h"

/* Tests object `index` of `kind` against the 16 rays and keeps, lane by lane, each hit that
 * beats `best` (common/hit_order.cl); without mirrors (CLR_LOOP_COLORS) also its flat colour
 * and, with alpha tests, the texel it shows. */
CLR_PACKET_INLINE void keep_nearer16(int kind, int index, real3 origin, Directions16 d, Hits16* best,
                                     Colors16* colors, uint16* best_texel, CLR_SCENE_PARAMS)
{
#if CLR_FEATURE_ALPHA
    uint16 texel = (uint16)(CLR_NO_TEXEL);
#else
    uint16 texel = (uint16)(0u);
#endif
    real16 t = kind_hit_distance16(kind, index, origin, d, CLR_LOOP_COLORS, &texel, CLR_SCENE_ARGS);
    mask16 beats = hits_beat16(t, kind, index, best->t, best->kind, best->index);
    int16 beats_int = convert_int16(beats);
    best->t = select(best->t, t, beats);
    best->kind = select(best->kind, (int16)(kind), beats_int);
    best->index = select(best->index, (int16)(index), beats_int);
#if CLR_LOOP_COLORS
    Colors16 flat = kind_flat_colors16(kind, index, texel, CLR_SCENE_ARGS);
    colors->r = select(colors->r, flat.r, beats_int);
    colors->g = select(colors->g, flat.g, beats_int);
    colors->b = select(colors->b, flat.b, beats_int);
#endif
#if CLR_LOOP_COLORS && CLR_FEATURE_ALPHA
    *best_texel = select(*best_texel, texel, beats_int);
#endif
}

#endif /* CLR_PACKET_KEEP_NEARER16_CL */
