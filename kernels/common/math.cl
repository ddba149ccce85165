/* Small device helpers shared by every stage. */

/* No fused multiply-adds: the 16-lane primary-ray path (intersect_packet.cl) and the scalar
 * path must compute bit-identical distances from the same formulas, on every device. */
#pragma OPENCL FP_CONTRACT OFF

/* Dot product written out, in a fixed order. The built-in dot() may be computed in another
 * order or with FMAs, which would make the scalar and 16-lane paths differ in the last bit. */
float dot3(float3 a, float3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

/* v / |v| with dot3, for the same reason. */
float3 unit3(float3 v)
{
    return v / sqrt(dot3(v, v));
}

/* Display byte for a colour channel: round(clamp(c, 0, 1) * 255), rounding halves up as
 * the host reference does (SPEC 2, Colour). */
uchar color_to_byte(float c)
{
    return (uchar)floor(clamp(c, 0.0f, 1.0f) * 255.0f + 0.5f);
}

/* Mirror direction of d about the unit normal n. */
float3 reflect_direction(float3 d, float3 n)
{
    return d - 2.0f * dot(d, n) * n;
}
