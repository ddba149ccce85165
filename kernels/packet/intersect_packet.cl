/* Primary rays 16 at a time: the 16 pixels of one row of a screen tile share the eye as
 * origin and the tile's object list, so each object is tested against all 16 rays with
 * 16-wide vector arithmetic (one AVX-512 instruction per operation on CPUs). PoCL does not
 * vectorise the scalar loop by itself (the running nearest hit defeats it), hence explicit
 * float16. Every formula is the scalar one of intersect.cl, operation for operation, so each
 * lane computes the same bits as the scalar path would (FP_CONTRACT is off, see math.cl). */
#ifndef CLR_PACKET_INTERSECT_PACKET_CL
#define CLR_PACKET_INTERSECT_PACKET_CL

#include "common/hit_order.cl"
#include "common/math.cl"
#include "common/prefetch.cl"
#include "common/rgba_words.cl"
#include "common/scene_items.cl"
#include "common/scene_params.cl"
#include "packet/lane_masks.cl"
#include "packet/packet_types.cl"
#include "packet/shading_modes.cl"
#include "packet/texels16.cl"
#include "shared/clr_types.h"

/* The 16 lanes' column offsets within the packet. */
#define CLR_LANES ((int16)(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15))

/* camera_ray_through() for pixels (col0 .. col0 + 15, row), at offsets (ox, oy) in them. */
CLR_PACKET_INLINE Directions16 camera_rays16(ClrCamera camera, int col0, int row, float16 ox, float16 oy)
{
    real16 col = convert_real16((int16)(col0) + CLR_LANES);
    real16 sx = 2.0f * (col + convert_real16(ox)) / (real)camera.width - 1.0f;
    real16 sy = 1.0f - 2.0f * ((real)row + convert_real16(oy)) / (real)camera.height;
    real3 forward = convert_real3(camera.forward.xyz), right = convert_real3(camera.right.xyz);
    real3 up = convert_real3(camera.up.xyz);
    Directions16 d;
    d.x = forward.x + sx * right.x + sy * up.x; /* as camera_ray_through() */
    d.y = forward.y + sx * right.y + sy * up.y;
    d.z = forward.z + sx * right.z + sy * up.z;
    real16 length = sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    d.x = d.x / length;
    d.y = d.y / length;
    d.z = d.z / length;
    return d;
}

CLR_PACKET_INLINE real16 dot16(real3 a, Directions16 d)
{
    return a.x * d.x + a.y * d.y + a.z * d.z;
}

/* sphere_distance() for 16 rays from one origin. */
CLR_PACKET_INLINE real16 sphere_distance16(float4 center_radius, real3 origin, Directions16 d)
{
    real radius = center_radius.w;
    real3 oc = origin - convert_real3(center_radius.xyz);
    real16 b = -dot16(oc, d);
    real16 cx = oc.x + b * d.x, cy = oc.y + b * d.y, cz = oc.z + b * d.z;
    real16 discriminant = radius * radius - (cx * cx + cy * cy + cz * cz);
    if (!any_lanes16(discriminant >= 0.0f))
        return (real16)(INFINITY); /* all 16 rays miss: skip the square root and division */
    real c = dot3(oc, oc) - radius * radius;
    real16 q = b + copysign(sqrt(discriminant), b);
    real16 t0 = c / q;
    real16 t1 = q;
    real16 t_near = fmin(t0, t1);
    real16 t_far = fmax(t0, t1);
    real16 t = select(select((real16)(INFINITY), t_far, t_far > 0.0f), t_near, t_near > 0.0f);
    return select(t, (real16)(INFINITY), discriminant < 0.0f || q == 0.0f);
}

/* A comparison of two int16 as a mask16 (what comparing two real16 gives). */
#if CLR_FEATURE_DOUBLE
#define CLR_MASK16(m) convert_long16(m)
#else
#define CLR_MASK16(m) (m)
#endif

/* billboard_distance() for 16 rays from one origin (t_max = infinity). When `want_texels`
 * and the billboard shows its image, *texel receives each hit lane's texel (for flat
 * shading), read at the same (a, b) as the alpha test and as billboard_color(): with
 * CLR_FEATURE_ALPHA its index in the texel buffer, which the caller reads only for the
 * winning hit, and the alpha test reads the coverage bits; otherwise the texel itself. */
CLR_PACKET_INLINE real16 billboard_distance16(__global const ClrBillboard* billboard, __global const uchar4* texels,
                                              __global const uint* coverage, real3 origin, Directions16 d,
                                              int want_texels, uint16* texel)
{
    real3 normal = convert_real3(billboard->normal.xyz);
    real3 corner = convert_real3(billboard->corner.xyz);
    real16 t = dot3(corner - origin, normal) / dot16(normal, d);
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

/* Colours of 16 lanes as flat shading gives them for surface `kind`, `index`: a sphere's
 * ambient or an untextured billboard's colour, or texel_color() of each lane's texel. With
 * CLR_FEATURE_ALPHA, `texel` holds texel indices, and a textured billboard's lanes get its
 * flat colour here: take_texel_colors16() gives the winners theirs after the loop. */
CLR_PACKET_INLINE Colors16 flat_colors16(int kind, int index, uint16 texel, CLR_SCENE_PARAMS)
{
    float3 color = (float3)(0.0f);
    int textured = 0;
#if CLR_FEATURE_BILLBOARDS
    if (kind == CLR_HIT_BILLBOARD) {
        color = billboards[index].color.xyz;
#if CLR_FEATURE_TEXTURES && !CLR_FEATURE_ALPHA
        textured = (billboards[index].flags & CLR_SURFACE_TEXTURED) != 0;
#endif
    }
#endif
#if CLR_FEATURE_SPHERES
    if (kind == CLR_HIT_SPHERE)
        color = spheres[index].color.xyz;
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

/* Distances along 16 primary rays from `origin` to surface `kind`, `index`, as
 * sphere_distance16() or billboard_distance16() give them. With `want_texels`, *texel
 * receives each lane's texel of a billboard that shows its image. */
CLR_PACKET_INLINE real16 item_distance16(int kind, int index, real3 origin, Directions16 d, int want_texels,
                                         uint16* texel, CLR_SCENE_PARAMS)
{
    real16 t = (real16)(INFINITY);
#if CLR_FEATURE_BILLBOARDS
    if (kind == CLR_HIT_BILLBOARD)
        t = billboard_distance16(&billboards[index], texels, coverage, origin, d, want_texels, texel);
#endif
#if CLR_FEATURE_SPHERES
    if (kind == CLR_HIT_SPHERE)
        t = sphere_distance16(spheres[index].center_radius, origin, d);
#endif
    return t;
}

#if CLR_FEATURE_ALPHA
/* Fetches the cache line of the first coverage bits of `item` if it is a billboard, ahead of
 * its alpha test: a forest's tile lists hundreds of billboards whose bits are not in cache. */
CLR_PACKET_INLINE void prefetch_coverage(uint item, __global const ClrBillboard* billboards,
                                         __global const uint* coverage)
{
    if (item_kind(item) == CLR_HIT_BILLBOARD)
        CLR_PREFETCH(coverage + (billboards[item_index(item)].texel_offset >> 5));
}
#endif

/* The nearest hits of 16 primary rays among the objects binned to their screen tile, skipping
 * those whose pixel rows leave out this `row`. The loop ends once every lane's hit is nearer
 * than every object left (the tile's items come nearest first). Hits are ranked by
 * hits_beat16() (common/hit_order.cl), so the visiting order does not matter and the answer
 * is intersect_scene()'s, ties included. Without mirrors (CLR_LOOP_COLORS), *colors receives
 * each lane's colour as flat shading gives it: the background or flat_colors16(); with a sun,
 * lanes on spheres still need shade_hit(). */
CLR_PACKET_INLINE void intersect_tile16(real3 origin, Directions16 d, int row, TileItems tile, CLR_SCENE_PARAMS,
                                        Hits16* best, Colors16* colors)
{
    best->t = (real16)(INFINITY);
    best->kind = (int16)(CLR_HIT_NONE);
    best->index = (int16)(-1);
#if CLR_LOOP_COLORS
    colors->r = (float16)(info.background.x);
    colors->g = (float16)(info.background.y);
    colors->b = (float16)(info.background.z);
#endif
#if CLR_LOOP_COLORS && CLR_FEATURE_ALPHA
    uint16 best_texel = (uint16)(CLR_NO_TEXEL); /* each lane's winning texel, read after the loop */
#endif
    for (uint k = tile.first; k < tile.end; ++k) {
        if (all_lanes16(best->t < tile.nearest[k]))
            break;
        uint rows = tile.rows[k]; /* first << 16 | last pixel row the object may cover */
        if ((uint)row < (rows >> 16) || (uint)row > (rows & 0xffffu))
            continue;
        int kind = item_kind(tile.items[k]);
        int index = item_index(tile.items[k]);
#if CLR_FEATURE_ALPHA
        if (k + 2 < tile.end) /* the coverage bits of the billboard two items on */
            prefetch_coverage(tile.items[k + 2], billboards, coverage);
#endif
#if CLR_FEATURE_ALPHA
        uint16 texel = (uint16)(CLR_NO_TEXEL);
#else
        uint16 texel = (uint16)(0u);
#endif
        real16 t = item_distance16(kind, index, origin, d, CLR_LOOP_COLORS, &texel, CLR_SCENE_ARGS);
        mask16 beats = hits_beat16(t, kind, index, best->t, best->kind, best->index);
        int16 beats_int = convert_int16(beats);
        best->t = select(best->t, t, beats);
        best->kind = select(best->kind, (int16)(kind), beats_int);
        best->index = select(best->index, (int16)(index), beats_int);
#if CLR_LOOP_COLORS
        Colors16 flat = flat_colors16(kind, index, texel, CLR_SCENE_ARGS);
        colors->r = select(colors->r, flat.r, beats_int);
        colors->g = select(colors->g, flat.g, beats_int);
        colors->b = select(colors->b, flat.b, beats_int);
#endif
#if CLR_LOOP_COLORS && CLR_FEATURE_ALPHA
        best_texel = select(best_texel, texel, beats_int);
#endif
    }
#if CLR_LOOP_COLORS && CLR_FEATURE_ALPHA
    take_texel_colors16(best_texel, texels, colors);
#endif
}

#endif /* CLR_PACKET_INTERSECT_PACKET_CL */
