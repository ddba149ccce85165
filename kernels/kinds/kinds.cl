/* The primitive kinds, in one list: CLR_KINDS names each kind's hit kind (CLR_HIT_*,
 * shared/clr_types.h), the prefix of its functions (kinds/<name>.cl) and the feature macro
 * that compiles it in (host/render/feature_set.h). Every stage reaches a kind's code through
 * the dispatchers below, generated from the list, and the scene's objects of kind <name> are
 * the buffer <name>s of CLR_SCENE_PARAMS, <name>_count of them (ClrSceneInfo). Adding a kind
 * is a line here, its file, and its buffer and count (docs/architecture.md, Adding a
 * primitive kind).
 *
 * Every kind's file defines, with these parameters:
 *   real <name>_hit_distance(int index, real3 origin, real3 direction, real t_max, CLR_SCENE_PARAMS)
 *     the hit's distance with 0 < t < t_max, or +inf
 *   real16 <name>_hit_distance16(int index, real3 origin, Directions16 d, int want_texels,
 *                                uint16* texel, CLR_SCENE_PARAMS)   the same for 16 primary rays
 *   real3 <name>_normal(int index, real3 point, real3 direction, CLR_SCENE_PARAMS)
 *     the unit front (outer) normal; a kind seen from both sides turns it to face `direction`
 *   uint <name>_flags(int index, CLR_SCENE_PARAMS)                  CLR_SURFACE_*
 *   uint <name>_material(int index, CLR_SCENE_PARAMS)     its material in `materials`
 *   float3 <name>_surface_color(int index, real3 origin, real3 direction, real t, CLR_SCENE_PARAMS)
 *     its colour before lighting
 *   Colors16 <name>_flat_colors16(int index, uint16 texel, CLR_SCENE_PARAMS)  the same, 16 lanes
 *   bool <name>_is_lit(void)      whether the sun lights it (shade.cl)
 *   void <name>_prefetch(int index, CLR_SCENE_PARAMS)   memory to fetch ahead of its test
 *
 * The list's order is the hit order's (common/hit_order.cl): kinds by CLR_HIT_* value. */
#ifndef CLR_KINDS_KINDS_CL
#define CLR_KINDS_KINDS_CL

#include "common/math.cl"
#include "common/scene_items.cl"
#include "common/scene_params.cl"
#include "kinds/billboard.cl"
#include "kinds/plane.cl"
#include "kinds/sphere.cl"
#include "kinds/triangle.cl"
#include "packet/packet_types.cl"
#include "shared/clr_types.h"

/* X(HIT_KIND, name, FEATURE) for each kind, by HIT_KIND. */
#define CLR_KINDS(X)                                      \
    X(CLR_HIT_SPHERE, sphere, CLR_FEATURE_SPHERES)        \
    X(CLR_HIT_BILLBOARD, billboard, CLR_FEATURE_BILLBOARDS)  \
    X(CLR_HIT_TRIANGLE, triangle, CLR_FEATURE_TRIANGLES)     \
    X(CLR_HIT_PLANE, plane, CLR_FEATURE_PLANES)

/* Object `index` of `kind` as a ray meets it (<name>_hit_distance). */
#define CLR_KIND_HIT_DISTANCE(KIND, name, FEATURE) \
    if (FEATURE && kind == KIND)                   \
        return name##_hit_distance(index, origin, direction, t_max, CLR_SCENE_ARGS);
real kind_hit_distance(int kind, int index, real3 origin, real3 direction, real t_max, CLR_SCENE_PARAMS)
{
    CLR_KINDS(CLR_KIND_HIT_DISTANCE)
    return INFINITY;
}

/* The same for 16 primary rays (<name>_hit_distance16). */
#define CLR_KIND_HIT_DISTANCE16(KIND, name, FEATURE) \
    if (FEATURE && kind == KIND)                     \
        return name##_hit_distance16(index, origin, d, want_texels, texel, CLR_SCENE_ARGS);
CLR_PACKET_INLINE real16 kind_hit_distance16(int kind, int index, real3 origin, Directions16 d, int want_texels,
                                             uint16* texel, CLR_SCENE_PARAMS)
{
    CLR_KINDS(CLR_KIND_HIT_DISTANCE16)
    return (real16)(INFINITY);
}

/* The nearest hit with 0 < t < t_max among all objects but (skip_kind, skip_index), kind by
 * kind and by index within each: the order that common/hit_order.cl ranks ties by, so
 * keeping the first of equal distances (t < hit.t) already is that rule. With `first_hit`,
 * the first hit found within t_max instead (a shadow ray's question, intersect.cl's
 * occluded()). */
#define CLR_KIND_NEAREST(KIND, name, FEATURE)                                                 \
    if (FEATURE) {                                                                            \
        for (int i = 0; i < info.name##_count; ++i) {                                         \
            if (skips_surface(KIND, i, skip_kind, skip_index))                                \
                continue;                                                                     \
            real t = name##_hit_distance(i, origin, direction, hit.t, CLR_SCENE_ARGS);        \
            if (t < hit.t) {                                                                  \
                hit.t = t;                                                                    \
                hit.kind = KIND;                                                              \
                hit.index = i;                                                                \
                if (first_hit)                                                                \
                    return hit;                                                               \
            }                                                                                 \
        }                                                                                     \
    }
Hit nearest_of_all_kinds(real3 origin, real3 direction, real t_max, int skip_kind, int skip_index, int first_hit,
                         CLR_SCENE_PARAMS)
{
    Hit hit;
    hit.t = t_max;
    hit.kind = CLR_HIT_NONE;
    hit.index = -1;
    CLR_KINDS(CLR_KIND_NEAREST)
    return hit;
}

/* The unit front normal of object `index` of `kind` at `point`, met along `direction`
 * (<name>_normal). */
#define CLR_KIND_NORMAL(KIND, name, FEATURE) \
    if (FEATURE && kind == KIND)             \
        return name##_normal(index, point, direction, CLR_SCENE_ARGS);
real3 kind_normal(int kind, int index, real3 point, real3 direction, CLR_SCENE_PARAMS)
{
    CLR_KINDS(CLR_KIND_NORMAL)
    return (real3)(0.0f);
}

/* The CLR_SURFACE_* flags of object `index` of `kind` (<name>_flags). */
#define CLR_KIND_FLAGS(KIND, name, FEATURE) \
    if (FEATURE && kind == KIND)            \
        return name##_flags(index, CLR_SCENE_ARGS);
uint kind_flags(int kind, int index, CLR_SCENE_PARAMS)
{
    CLR_KINDS(CLR_KIND_FLAGS)
    return 0u;
}

/* The Blinn-Phong material of object `index` of `kind` (<name>_material). */
#define CLR_KIND_MATERIAL(KIND, name, FEATURE) \
    if (FEATURE && kind == KIND)               \
        return name##_material(index, CLR_SCENE_ARGS);
uint kind_material(int kind, int index, CLR_SCENE_PARAMS)
{
    CLR_KINDS(CLR_KIND_MATERIAL)
    return 0u;
}

/* The colour before lighting at distance t (<name>_surface_color). */
#define CLR_KIND_SURFACE_COLOR(KIND, name, FEATURE) \
    if (FEATURE && kind == KIND)                    \
        return name##_surface_color(index, origin, direction, t, CLR_SCENE_ARGS);
float3 kind_surface_color(int kind, int index, real3 origin, real3 direction, real t, CLR_SCENE_PARAMS)
{
    CLR_KINDS(CLR_KIND_SURFACE_COLOR)
    return (float3)(0.0f);
}

/* The colours of 16 lanes on object `index` of `kind`, as flat shading gives them
 * (<name>_flat_colors16). */
#define CLR_KIND_FLAT_COLORS16(KIND, name, FEATURE) \
    if (FEATURE && kind == KIND)                    \
        return name##_flat_colors16(index, texel, CLR_SCENE_ARGS);
CLR_PACKET_INLINE Colors16 kind_flat_colors16(int kind, int index, uint16 texel, CLR_SCENE_PARAMS)
{
    CLR_KINDS(CLR_KIND_FLAT_COLORS16)
    Colors16 none;
    none.r = none.g = none.b = (float16)(0.0f);
    return none;
}

/* Whether the sun lights surfaces of `kind` (<name>_is_lit); CLR_HIT_NONE is not lit. */
#define CLR_KIND_IS_LIT(KIND, name, FEATURE) \
    if (kind == KIND)                        \
        return name##_is_lit();
bool kind_is_lit(int kind)
{
    CLR_KINDS(CLR_KIND_IS_LIT)
    return false;
}

/* kind_is_lit() of 16 lanes' kinds, as a comparison's mask. */
#define CLR_KIND_LIT_LANES16(KIND, name, FEATURE) \
    if (name##_is_lit())                          \
        lit = lit | (kinds == (int16)(KIND));
CLR_PACKET_INLINE int16 lit_lanes16(int16 kinds)
{
    int16 lit = (int16)(0);
    CLR_KINDS(CLR_KIND_LIT_LANES16)
    return lit;
}

/* Fetches what the test of `item` will read, ahead of it (<name>_prefetch). */
#define CLR_KIND_PREFETCH(KIND, name, FEATURE) \
    if (FEATURE && kind == KIND)               \
        name##_prefetch(index, CLR_SCENE_ARGS);
CLR_PACKET_INLINE void prefetch_item(uint item, CLR_SCENE_PARAMS)
{
    int kind = item_kind(item);
    int index = item_index(item);
    CLR_KINDS(CLR_KIND_PREFETCH)
}

#endif /* CLR_KINDS_KINDS_CL */
