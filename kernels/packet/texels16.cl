/* Billboard texels for 16 rays at once: which texel each lane's point shows, its RGBA word,
 * and, with alpha tests (CLR_FEATURE_ALPHA), whether it stops rays, read from the coverage
 * bits instead of the texel (docs/architecture.md, Coverage masks). */
#ifndef CLR_PACKET_TEXELS16_CL
#define CLR_PACKET_TEXELS16_CL

#include "common/math.cl"
#include "common/rgba_words.cl"
#include "packet/lane_masks.cl"
#include "packet/packet_types.cl"
#include "shared/clr_types.h"

#if CLR_FEATURE_ALPHA || CLR_FEATURE_TEXTURES
/* The texel buffer indices that billboard_texel() reads for 16 points (a, b) of one
 * billboard. Lanes outside the billboard (`inside` false) get its first texel instead. */
CLR_PACKET_INLINE uint16 billboard_texel_indices16(__global const ClrBillboard* billboard, real16 a, real16 b,
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
    return billboard->texel_offset + convert_uint16(row) * (uint)width + convert_uint16(col);
}

/* The texels at indices i, as 32-bit words (RGBA bytes): a gather of 16 loads. */
CLR_PACKET_INLINE uint16 texel_words16(__global const uchar4* texels, uint16 i)
{
    __global const uint* w = (__global const uint*)texels;
    return (uint16)(w[i.s0], w[i.s1], w[i.s2], w[i.s3], w[i.s4], w[i.s5], w[i.s6], w[i.s7], w[i.s8], w[i.s9],
                    w[i.sa], w[i.sb], w[i.sc], w[i.sd], w[i.se], w[i.sf]);
}
#endif

#if CLR_FEATURE_ALPHA
/* A lane that shows no texel: no texel has this index (the host keeps every index below
 * 2^32 - 1, compiled_scene.cpp). */
#define CLR_NO_TEXEL 0xffffffffu

/* v[i & 15] in each lane. LLVM makes one permute instruction of it (vpermd on AVX-512), not
 * 16 loads, when v is in registers. */
CLR_PACKET_INLINE uint16 permute16(uint16 v, uint16 i)
{
    i &= (uint16)(15u);
    return (uint16)(v[i.s0], v[i.s1], v[i.s2], v[i.s3], v[i.s4], v[i.s5], v[i.s6], v[i.s7], v[i.s8], v[i.s9],
                    v[i.sa], v[i.sb], v[i.sc], v[i.sd], v[i.se], v[i.sf]);
}

/* Whether the texels at indices i of `billboard`'s image stop rays: bit i % 32 of coverage
 * word i / 32, which the host set exactly where the texel's alpha is CLR_OPAQUE_ALPHA (the
 * test billboard_distance() makes on the texel itself). When the image's bits lie within
 * CLR_COVERAGE_WINDOW_WORDS words, two vector loads read them all and permutes pick each
 * lane's word; a larger image's words come by a gather of 16 loads, whose latency was a
 * tenth of a small scene's frame (docs/benchmarks.md, Prefetching and coverage windows). */
CLR_PACKET_INLINE int16 covered16(__global const uint* coverage, __global const ClrBillboard* billboard, uint16 i)
{
    uint first = billboard->texel_offset >> 5;
    uint texels = (uint)billboard->texture_width * (uint)billboard->texture_height;
    uint last = (billboard->texel_offset + texels - 1u) >> 5;
    uint16 word = i >> 5u;
    uint16 words;
    if (last - first < CLR_COVERAGE_WINDOW_WORDS) { /* the host pads the buffer for this read */
        uint16 in_window = word - (uint16)(first);
        uint16 low = vload16(0, coverage + first), high = vload16(1, coverage + first);
        words = select(permute16(low, in_window), permute16(high, in_window), in_window >= 16u);
    } else {
        words = (uint16)(coverage[word.s0], coverage[word.s1], coverage[word.s2], coverage[word.s3],
                         coverage[word.s4], coverage[word.s5], coverage[word.s6], coverage[word.s7],
                         coverage[word.s8], coverage[word.s9], coverage[word.sa], coverage[word.sb],
                         coverage[word.sc], coverage[word.sd], coverage[word.se], coverage[word.sf]);
    }
    /* A one-bit mask per lane, not (words >> (i & 31)) & 1, which PoCL computes right but
     * which, inlined here, lost 12% of a textured frame's hits under Oclgrind 21.10
     * (docs/opencl-devices.md). */
    return (words & ((uint16)(1u) << (i & 31u))) != 0u;
}

/* Lanes whose winning hit shows texel texel_index[lane] (not CLR_NO_TEXEL) take that texel's
 * colour, texel_color(); the others keep theirs. One gather of texels per row of 16 rays,
 * whatever number of textured billboards the rays tested on the way. */
CLR_PACKET_INLINE void take_texel_colors16(uint16 texel_index, __global const uchar4* texels, Colors16* colors)
{
    int16 shows = texel_index != (uint16)(CLR_NO_TEXEL);
    if (!any_lanes16(shows))
        return;
    uint16 words = texel_words16(texels, select((uint16)(0u), texel_index, shows));
    colors->r = select(colors->r, convert_float16(CLR_RGBA_CHANNEL(words, 0u)) * (1.0f / 255.0f), shows);
    colors->g = select(colors->g, convert_float16(CLR_RGBA_CHANNEL(words, 1u)) * (1.0f / 255.0f), shows);
    colors->b = select(colors->b, convert_float16(CLR_RGBA_CHANNEL(words, 2u)) * (1.0f / 255.0f), shows);
}
#endif

#endif /* CLR_PACKET_TEXELS16_CL */
