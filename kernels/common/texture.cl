/* Billboard images: every image's texels sit in one buffer of RGBA bytes, rows from the
 * top, and each billboard knows where its image starts (ClrBillboard.texel_offset). */
#ifndef CLR_COMMON_TEXTURE_CL
#define CLR_COMMON_TEXTURE_CL

#include "common/math.cl"
#include "shared/clr_types.h"

/* The texel shown at billboard coordinates (a, b) in [0, 1]: column floor(a*W), row
 * floor(b*H), clamped so that a == 1 or b == 1 stays on the image (docs/scene-format.md,
 * Conventions: Billboards). */
uchar4 billboard_texel(__global const ClrBillboard* billboard, __global const uchar4* texels, real a, real b)
{
    int width = billboard->texture_width;
    int height = billboard->texture_height;
    int col = clamp((int)floor(a * (real)width), 0, width - 1);
    int row = clamp((int)floor(b * (real)height), 0, height - 1);
    return texels[billboard->texel_offset + (uint)row * (uint)width + (uint)col];
}

float3 texel_color(uchar4 texel)
{
    return convert_float3(texel.xyz) * (1.0f / 255.0f);
}

#endif /* CLR_COMMON_TEXTURE_CL */
