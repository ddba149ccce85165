/* Small device helpers shared by every stage. */

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
