/* Primary rays 16 at a time: the 16 pixels of one row of a screen tile share the eye as
 * origin and the tile's object list, so each object is tested against all 16 rays with
 * 16-wide vector arithmetic (one AVX-512 instruction per operation on CPUs). PoCL does not
 * vectorise the scalar loop by itself (the running nearest hit defeats it), hence explicit
 * float16. Every formula is the scalar one of intersect.cl, operation for operation, so each
 * lane computes the same bits as the scalar path would (FP_CONTRACT is off, see math.cl). */

typedef struct {
    real16 x, y, z;
} Directions16;

/* The packet functions are inlined into render_packets: called, they pass their 16-lane
 * vectors and results through the stack. */
#define CLR_PACKET_INLINE __attribute__((always_inline))

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
    if (!any(discriminant >= 0.0f))
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

/* Flat shading (no sun, no mirrors): a primary ray's colour is its nearest surface's own
 * colour, so render_packets takes it from the intersection loop, 16 lanes at a time, instead
 * of shading lane by lane (the same values as shade_hit(): see intersect_tile16). */
#define CLR_FLAT_SHADING (!CLR_FEATURE_SUN && !CLR_FEATURE_MIRRORS)
/* Without mirrors, every lane that does not end on a sphere shows a flat colour (the
 * background, or a billboard's texel or colour: billboards are unlit), so the loop provides
 * it even with a sun; only lanes on spheres are then shaded one by one. */
#define CLR_LOOP_COLORS (!CLR_FEATURE_MIRRORS)

/* A comparison of two int16 as a mask16 (what comparing two real16 gives). */
#if CLR_FEATURE_DOUBLE
#define CLR_MASK16(m) convert_long16(m)
#else
#define CLR_MASK16(m) (m)
#endif

/* Channel c (0 red .. 3 alpha) of texels read as 32-bit words. */
#if __ENDIAN_LITTLE__
#define CLR_TEXEL_CHANNEL(words, c) (((words) >> (8u * (c))) & 0xffu)
#else
#define CLR_TEXEL_CHANNEL(words, c) (((words) >> (24u - 8u * (c))) & 0xffu)
#endif

#if CLR_FEATURE_ALPHA || CLR_FEATURE_TEXTURES
/* billboard_texel() for 16 points (a, b) of one billboard, as 32-bit words (RGBA bytes).
 * Lanes outside the billboard (`inside` false) read its first texel instead. The index is the
 * scalar formula in 16 lanes; the loads are a gather. */
CLR_PACKET_INLINE uint16 billboard_texels16(__global const ClrBillboard* billboard, __global const uchar4* texels, real16 a, real16 b,
                          mask16 inside)
{
    int width = billboard->texture_width;
    int height = billboard->texture_height;
    a = select((real16)(0.0f), a, inside); /* no float-to-int conversion of NaN or inf */
    b = select((real16)(0.0f), b, inside);
    /* Vector bounds, not the scalar-bound overload clamp(int16, int, int): both are standard,
     * but Oclgrind 21.10 gives garbage in lanes 1-15 of the scalar-bound integer
     * clamp/min/max, which then gathers far outside the texel buffer (docs/opencl-devices.md). */
    int16 col = clamp(convert_int16(floor(a * (real)width)), (int16)(0), (int16)(width - 1));
    int16 row = clamp(convert_int16(floor(b * (real)height)), (int16)(0), (int16)(height - 1));
    uint16 i = billboard->texel_offset + convert_uint16(row) * (uint)width + convert_uint16(col);
    __global const uint* w = (__global const uint*)texels;
    return (uint16)(w[i.s0], w[i.s1], w[i.s2], w[i.s3], w[i.s4], w[i.s5], w[i.s6], w[i.s7], w[i.s8], w[i.s9],
                    w[i.sa], w[i.sb], w[i.sc], w[i.sd], w[i.se], w[i.sf]);
}
#endif

/* billboard_distance() for 16 rays from one origin (t_max = infinity). When `want_texels`
 * and the billboard shows its image, *texel receives each hit lane's texel (for flat
 * shading), read at the same (a, b) as the alpha test and as billboard_color(). */
CLR_PACKET_INLINE real16 billboard_distance16(__global const ClrBillboard* billboard, __global const uchar4* texels, real3 origin,
                            Directions16 d, int want_texels, uint16* texel)
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
    if ((holes || textured) && any(inside)) {
        uint16 words = billboard_texels16(billboard, texels, a, b, inside);
        *texel = words;
        if (holes) /* a texel with alpha below 255 is a hole */
            inside = inside && CLR_MASK16(convert_int16(CLR_TEXEL_CHANNEL(words, 3u) == 255u));
    }
#endif
    return select((real16)(INFINITY), t, inside);
}

/* The nearest hits of 16 primary rays among the objects binned to their screen tile
 * (items[first] .. items[end - 1], nearest first; see host/render/screen_tiles.h), skipping
 * those whose pixel rows (item_rows) leave out this `row`. The loop
 * ends once every lane's hit is nearer than every object left (item_nearest holds a lower
 * bound on each object's hit distance). Hits are compared by (t, kind, index): nearer, or as
 * near and first in intersect_scene()'s order (spheres, then billboards, by index), so the
 * visiting order does not matter and the answer is intersect_scene()'s, ties included.
 * Without mirrors (CLR_LOOP_COLORS), *r, *g, *b receive each lane's colour as flat shading
 * gives it: the background, a sphere's ambient or untextured billboard's colour, or
 * texel_color() of its texel; with a sun, lanes on spheres still need shade_hit(). */
CLR_PACKET_INLINE void intersect_tile16(real3 origin, Directions16 d, int row, __global const uint* items,
                      __global const float* item_nearest, __global const uint* item_rows, uint first, uint end, CLR_SCENE_PARAMS, real16* best_t, int16* best_kind, int16* best_index,
                      float16* r, float16* g, float16* b)
{
    *best_t = (real16)(INFINITY);
    *best_kind = (int16)(CLR_HIT_NONE);
    *best_index = (int16)(-1);
#if CLR_LOOP_COLORS
    *r = (float16)(info.background.x);
    *g = (float16)(info.background.y);
    *b = (float16)(info.background.z);
#endif
    for (uint k = first; k < end; ++k) {
        if (all(*best_t < item_nearest[k]))
            break;
        uint rows = item_rows[k]; /* first << 16 | last pixel row the object may cover */
        if ((uint)row < (rows >> 16) || (uint)row > (rows & 0xffffu))
            continue;
        uint item = items[k];
        int index = (int)(item & ~CLR_TILE_BILLBOARD);
        int kind = (item & CLR_TILE_BILLBOARD) ? CLR_HIT_BILLBOARD : CLR_HIT_SPHERE;
        real16 t = (real16)(INFINITY);
        float3 color = (float3)(0.0f);
        uint16 texel = (uint16)(0u);
        int textured = 0;
#if CLR_FEATURE_BILLBOARDS
        if (kind == CLR_HIT_BILLBOARD) {
            t = billboard_distance16(&billboards[index], texels, origin, d, CLR_LOOP_COLORS, &texel);
            color = billboards[index].color.xyz;
#if CLR_FEATURE_TEXTURES
            textured = (billboards[index].flags & CLR_SURFACE_TEXTURED) != 0;
#endif
        }
#endif
#if CLR_FEATURE_SPHERES
        if (kind == CLR_HIT_SPHERE) {
            t = sphere_distance16(spheres[index].center_radius, origin, d);
            color = spheres[index].color.xyz;
        }
#endif
        int16 order_first = kind < *best_kind || (kind == *best_kind && index < *best_index);
        mask16 beats = t < *best_t || (t == *best_t && t < INFINITY && convert_real16(order_first) != 0.0f);
        int16 beats_int = convert_int16(beats);
        *best_t = select(*best_t, t, beats);
        *best_kind = select(*best_kind, (int16)(kind), beats_int);
        *best_index = select(*best_index, (int16)(index), beats_int);
#if CLR_LOOP_COLORS
        float16 cr = (float16)(color.x), cg = (float16)(color.y), cb = (float16)(color.z);
        if (textured) { /* texel_color() */
            cr = convert_float16(CLR_TEXEL_CHANNEL(texel, 0u)) * (1.0f / 255.0f);
            cg = convert_float16(CLR_TEXEL_CHANNEL(texel, 1u)) * (1.0f / 255.0f);
            cb = convert_float16(CLR_TEXEL_CHANNEL(texel, 2u)) * (1.0f / 255.0f);
        }
        *r = select(*r, cr, beats_int);
        *g = select(*g, cg, beats_int);
        *b = select(*b, cb, beats_int);
#endif
    }
}
