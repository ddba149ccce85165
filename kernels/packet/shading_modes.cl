/* How render_packets colours its 16 lanes, chosen by the program's features. */
#ifndef CLR_PACKET_SHADING_MODES_CL
#define CLR_PACKET_SHADING_MODES_CL

/* Flat shading (no sun, no lights, no mirrors): a primary ray's colour is its nearest
 * surface's own colour, so render_packets takes it from the intersection loop, 16 lanes at a
 * time, instead of shading lane by lane (the same values as shade_hit(): see intersect_tile16). */
#define CLR_FLAT_SHADING (!CLR_FEATURE_SUN && !CLR_FEATURE_LIGHTS && !CLR_FEATURE_MIRRORS)
/* Without mirrors, every lane that does not end on a lit kind shows a flat colour (the
 * background, or a billboard's texel or colour: billboards are unlit), so the loop provides
 * it even with a sun or lights; only lanes on lit kinds are then shaded one by one (a
 * material's mirror share k_m is followed there too, in trace_path()). */
#define CLR_LOOP_COLORS (!CLR_FEATURE_MIRRORS)
/* The sun alone (no lights, no mirrors) through a BVH: the lanes' shadow rays walk the BVH
 * together (packet/shadows16.cl), the one shading step not done 16 lanes at a time. */
#define CLR_SUN_PACKETS (CLR_FEATURE_SUN && CLR_FEATURE_BVH && !CLR_FEATURE_LIGHTS && !CLR_FEATURE_MIRRORS)

#endif /* CLR_PACKET_SHADING_MODES_CL */
