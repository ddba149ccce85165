/* The billboard kind (ClrBillboard): a parallelogram showing a flat colour or an image whose
 * transparent texels are holes. Where a ray meets it, one ray and 16 at a time, its normal and
 * its colour, as kinds/kinds.cl asks every kind. */
#ifndef CLR_KINDS_BILLBOARD_CL
#define CLR_KINDS_BILLBOARD_CL

#include "common/math.cl"
#include "common/prefetch.cl"
#include "common/rgba_words.cl"
#include "common/scene_params.cl"
#include "common/texture.cl"
#include "packet/lane_masks.cl"
#include "packet/packet_types.cl"
#include "packet/texels16.cl"
#include "shared/clr_types.h"

/* Billboard coordinates (a, b) of the point at distance t along the ray. Used both when
 * testing a hit and when shading it, so the alpha test and the colour read the same texel. */
real2 billboard_coords(__global const ClrBillboard* billboard, real3 origin, real3 direction, real t)
{
    real3 from_corner = (origin - convert_real3(billboard->corner.xyz)) + t * direction; /* P - UL */
    return (real2)(dot3(from_corner, convert_real3(billboard->dual_a.xyz)),
                   dot3(from_corner, convert_real3(billboard->dual_b.xyz)));
}

/* The origin's offset (UL - o).n from the billboard's plane, the more exact of two ways. From
 * the corner as stored: the corner is rounded to float relative to the eye, so the plane of a
 * billboard far larger than its distance from the eye (a tilted ground 1e12 across under an
 * eye 1.4 above it) passed units off the eye's surroundings, and the billboard vanished. From
 * the plane's offset from the eye, which the host computed in double (ClrBillboard normal.w),
 * less n.o: exact near the eye (o = 0 for a primary ray). The second is taken only where the
 * first's rounding bound is 4096 times its own, so that every billboard not so large keeps its
 * bits. That needs 4096 |stored| < |(UL - eye).n|, summed by component, whatever the origin; the
 * host marks the billboards that meet it with a margin (CLR_SURFACE_NEAR_EYE), and the others
 * take the first without the test. */
real billboard_offset(__global const ClrBillboard* billboard, real3 corner, real3 normal, real3 origin)
{
    real3 to_corner = corner - origin;
    if (!(billboard->flags & CLR_SURFACE_NEAR_EYE))
        return dot3(to_corner, normal);
    real stored = (real)billboard->normal.w;
    real eye_error = fabs(stored) + abs_dot3(normal, origin);
    return eye_error * 4096.0f < abs_dot3(to_corner, normal) ? stored - dot3(normal, origin) : dot3(to_corner, normal);
}

/* Distance along the ray to the billboard's plane if the ray meets the parallelogram there
 * at an opaque texel with 0 < t < t_max, else +inf. A ray parallel to the plane divides by
 * zero; the resulting inf or NaN fails the range test, so no special case is needed. */
real billboard_distance(__global const ClrBillboard* billboard, __global const uchar4* texels, real3 origin,
                        real3 direction, real t_max)
{
    real3 normal = convert_real3(billboard->normal.xyz);
    real t = billboard_offset(billboard, convert_real3(billboard->corner.xyz), normal, origin) / dot3(direction, normal);
    if (!(t > 0.0f && t < t_max))
        return INFINITY;
    real2 ab = billboard_coords(billboard, origin, direction, t);
    if (!(ab.x >= 0.0f && ab.x <= 1.0f && ab.y >= 0.0f && ab.y <= 1.0f))
        return INFINITY;
#if CLR_FEATURE_ALPHA
    /* A texel with alpha below CLR_OPAQUE_ALPHA is a hole: the ray goes on as if nothing were
     * here. */
    if ((billboard->flags & CLR_SURFACE_HOLES) && billboard_texel(billboard, texels, ab.x, ab.y).w < CLR_OPAQUE_ALPHA)
        return INFINITY;
#endif
    return t;
}

/* A comparison of two int16 as a mask16 (what comparing two real16 gives). */
#if CLR_FEATURE_DOUBLE
#define CLR_MASK16(m) convert_long16(m)
#else
#define CLR_MASK16(m) (m)
#endif

/* billboard_distance() for 16 rays from one origin (t_max = infinity). When `want_texels`
 * and the billboard shows its image, *texel receives each hit lane's texel (for flat
 * shading), read at the same (a, b) as the alpha test and as billboard_surface_color(): with
 * CLR_FEATURE_ALPHA its index in the texel buffer, which the caller reads only for the
 * winning hit, and the alpha test reads the coverage bits; otherwise the texel itself. */
CLR_PACKET_INLINE real16 billboard_distance16(__global const ClrBillboard* billboard, __global const uchar4* texels,
                                              __global const uint* coverage, real3 origin, Directions16 d,
                                              int want_texels, uint16* texel)
{
    real3 normal = convert_real3(billboard->normal.xyz);
    real3 corner = convert_real3(billboard->corner.xyz);
    real16 t = billboard_offset(billboard, corner, normal, origin) / dot16(normal, d);
    real3 origin_from_corner = origin - corner;
    real16 fx = origin_from_corner.x + t * d.x;
    real16 fy = origin_from_corner.y + t * d.y;
    real16 fz = origin_from_corner.z + t * d.z;
    real3 da = convert_real3(billboard->dual_a.xyz), db = convert_real3(billboard->dual_b.xyz);
    real16 a = fx * da.x + fy * da.y + fz * da.z;
    real16 b = fx * db.x + fy * db.y + fz * db.z;
    mask16 inside = t > 0.0f && t < INFINITY && a >= 0.0f && a <= 1.0f && b >= 0.0f && b <= 1.0f;
#if CLR_FEATURE_ALPHA || CLR_FEATURE_TEXTURES
    uint flags = billboard->flags;
    int holes = 0, textured = 0;
#if CLR_FEATURE_ALPHA
    holes = (flags & CLR_SURFACE_HOLES) != 0;
#endif
#if CLR_FEATURE_TEXTURES
    textured = want_texels && (flags & CLR_SURFACE_TEXTURED) != 0;
#endif
    if ((holes || textured) && any_lanes16(inside)) {
        uint16 i = billboard_texel_indices16(billboard, a, b, inside);
#if CLR_FEATURE_ALPHA
        if (holes) /* a texel with alpha below CLR_OPAQUE_ALPHA is a hole */
            inside = inside && CLR_MASK16(covered16(coverage, billboard, i));
        if (textured) {
            *texel = i;
            /* The winners' texels are read after the loop: fetch their cache lines now. A row
             * of 16 pixels crossing one billboard reads few texel lines (one per texel row it
             * crosses), so three lanes' lines stand for all 16. */
            __global const uint* words = (__global const uint*)texels;
            CLR_PREFETCH(words + i.s0);
            CLR_PREFETCH(words + i.s7);
            CLR_PREFETCH(words + i.sf);
        }
#else
        *texel = texel_words16(texels, i);
#endif
    }
#endif
    return select((real16)(INFINITY), t, inside);
}

/* billboard_distance() for 16 rays from 16 origins (t_max = infinity), the shadow rays of a
 * packet's hit points (packet/shadows16.cl): lane by lane the same operations in the same
 * order, so each lane's t is the one billboard_distance() gives its ray, to the last bit; a
 * hole is read from the coverage bits, as billboard_distance16() reads it. */
CLR_PACKET_INLINE real16 billboard_distance16_from(__global const ClrBillboard* billboard, __global const uint* coverage,
                                                   Points16 o, Directions16 d)
{
    real3 normal = convert_real3(billboard->normal.xyz);
    real3 corner = convert_real3(billboard->corner.xyz);
    /* billboard_offset(), then over dot3(direction, normal) */
    real16 ex = corner.x - o.x, ey = corner.y - o.y, ez = corner.z - o.z;
    real16 offset = ex * normal.x + ey * normal.y + ez * normal.z;
    if (billboard->flags & CLR_SURFACE_NEAR_EYE) {
        real stored = (real)billboard->normal.w;
        real16 eye_error = fabs(stored) + (fabs(normal.x * o.x) + fabs(normal.y * o.y) + fabs(normal.z * o.z));
        offset = select(offset, stored - (normal.x * o.x + normal.y * o.y + normal.z * o.z),
                        eye_error * 4096.0f < fabs(ex * normal.x) + fabs(ey * normal.y) + fabs(ez * normal.z));
    }
    real16 t = offset / (d.x * normal.x + d.y * normal.y + d.z * normal.z);
    /* billboard_coords(): (origin - corner) + t * direction, then its dots with the duals */
    real16 fx = (o.x - corner.x) + t * d.x;
    real16 fy = (o.y - corner.y) + t * d.y;
    real16 fz = (o.z - corner.z) + t * d.z;
    real3 da = convert_real3(billboard->dual_a.xyz), db = convert_real3(billboard->dual_b.xyz);
    real16 a = fx * da.x + fy * da.y + fz * da.z;
    real16 b = fx * db.x + fy * db.y + fz * db.z;
    mask16 inside = t > 0.0f && t < INFINITY && a >= 0.0f && a <= 1.0f && b >= 0.0f && b <= 1.0f;
#if CLR_FEATURE_ALPHA
    if ((billboard->flags & CLR_SURFACE_HOLES) && any_lanes16(inside)) /* a hole lets the ray on */
        inside = inside && CLR_MASK16(covered16(coverage, billboard, billboard_texel_indices16(billboard, a, b, inside)));
#endif
    return select((real16)(INFINITY), t, inside);
}

/* The kind's functions for kinds/kinds.cl. */

/* Billboard `index` as a ray from `origin` meets it at an opaque texel, with 0 < t < t_max,
 * or +inf. */
real billboard_hit_distance(int index, real3 origin, real3 direction, real t_max, CLR_SCENE_PARAMS)
{
    return billboard_distance(&billboards[index], texels, origin, direction, t_max);
}

/* billboard_hit_distance() for 16 primary rays, with each lane's texel as
 * billboard_distance16() gives it. */
CLR_PACKET_INLINE real16 billboard_hit_distance16(int index, real3 origin, Directions16 d, int want_texels,
                                                  uint16* texel, CLR_SCENE_PARAMS)
{
    return billboard_distance16(&billboards[index], texels, coverage, origin, d, want_texels, texel);
}

/* The unit front normal, the same at every point. */
real3 billboard_normal(int index, real3 point, real3 direction, CLR_SCENE_PARAMS)
{
    return convert_real3(billboards[index].normal.xyz);
}

uint billboard_flags(int index, CLR_SCENE_PARAMS)
{
    return billboards[index].flags;
}

/* Its Blinn-Phong material (ClrMaterial) in `materials`. */
uint billboard_material(int index, CLR_SCENE_PARAMS)
{
    return 0u; /* billboards are not lit: no material */
}

/* The colour a billboard shows at distance t: its texel (opaque, or the ray would have
 * passed through) or its flat colour. */
float3 billboard_surface_color(int index, real3 origin, real3 direction, real t, CLR_SCENE_PARAMS)
{
    __global const ClrBillboard* billboard = &billboards[index];
#if CLR_FEATURE_TEXTURES
    if (billboard->flags & CLR_SURFACE_TEXTURED) {
        real2 ab = billboard_coords(billboard, origin, direction, t);
        return texel_color(billboard_texel(billboard, texels, ab.x, ab.y));
    }
#endif
    return billboard->color.xyz;
}

/* billboard_surface_color() of 16 lanes that hit the billboard, from the texels that
 * billboard_distance16() gave. With CLR_FEATURE_ALPHA, `texel` holds texel indices and the
 * lanes get the flat colour here: take_texel_colors16() gives the winners theirs after the
 * packet loop. */
CLR_PACKET_INLINE Colors16 billboard_flat_colors16(int index, uint16 texel, CLR_SCENE_PARAMS)
{
    float3 color = billboards[index].color.xyz;
    int textured = 0;
#if CLR_FEATURE_TEXTURES && !CLR_FEATURE_ALPHA
    textured = (billboards[index].flags & CLR_SURFACE_TEXTURED) != 0;
#endif
    Colors16 out;
    out.r = (float16)(color.x);
    out.g = (float16)(color.y);
    out.b = (float16)(color.z);
    if (textured) { /* texel_color() */
        out.r = convert_float16(CLR_RGBA_CHANNEL(texel, 0u)) * (1.0f / 255.0f);
        out.g = convert_float16(CLR_RGBA_CHANNEL(texel, 1u)) * (1.0f / 255.0f);
        out.b = convert_float16(CLR_RGBA_CHANNEL(texel, 2u)) * (1.0f / 255.0f);
    }
    return out;
}

/* Billboards are pictures: never lit (docs/scene-format.md, Conventions: Lighting and
 * shadows). */
bool billboard_is_lit(void)
{
    return false;
}

/* With alpha tests, fetches the cache line of the billboard's first coverage bits ahead of
 * its test: a forest's tile lists hundreds of billboards whose bits are not in cache. */
CLR_PACKET_INLINE void billboard_prefetch(int index, CLR_SCENE_PARAMS)
{
#if CLR_FEATURE_ALPHA
    CLR_PREFETCH(coverage + (billboards[index].texel_offset >> 5));
#endif
}

#endif /* CLR_KINDS_BILLBOARD_CL */
