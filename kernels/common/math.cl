/* Small device helpers shared by every stage: the `real` type, the in-kernel Ray and Hit,
 * and arithmetic written out so that every path computes the same bits. */
#ifndef CLR_COMMON_MATH_CL
#define CLR_COMMON_MATH_CL

#include "shared/clr_types.h"

/* No fused multiply-adds: the 16-lane primary-ray path (intersect_packet.cl) and the scalar
 * path must compute bit-identical distances from the same formulas, on every device. */
#pragma OPENCL FP_CONTRACT OFF

/* Geometry runs in `real`: float by default, double with CLR_FEATURE_DOUBLE (--precision
 * double, on devices with cl_khr_fp64). Colours stay float; the shared structs stay float4. */
#if CLR_FEATURE_DOUBLE
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
typedef double real;
typedef double2 real2;
typedef double3 real3;
typedef double4 real4;
typedef double16 real16;
typedef long16 mask16; /* what comparing two real16 gives */
#define convert_mask16 convert_long16
#define convert_real3 convert_double3
#define convert_real16 convert_double16
#else
typedef float real;
typedef float2 real2;
typedef float3 real3;
typedef float4 real4;
typedef float16 real16;
typedef int16 mask16;
#define convert_mask16 convert_int16
#define convert_real3 convert_float3
#define convert_real16 convert_float16
#endif

/* A ray inside the kernels, in `real`; ClrRay is its float form in buffers. */
typedef struct {
    real3 origin;
    real3 direction; /* unit length */
} Ray;

/* A secondary ray leaves surface (skip_kind, skip_index). From a settled triangle hit
 * (kinds/triangle.cl, triangle_settled_index()) it leaves two triangles: the one hit
 * (skip_index) and the lowest other one at its edge or corner, encoded in skip_kind as
 * CLR_SKIP_PAIR - other. */
#define CLR_SKIP_PAIR (-16)
int skip_kind_of_pair(int hit_index, int other)
{
    return other == hit_index ? CLR_HIT_TRIANGLE : CLR_SKIP_PAIR - other;
}
bool skips_surface(int kind, int index, int skip_kind, int skip_index)
{
#if CLR_FEATURE_TRIANGLE_TIES
    if (skip_kind <= CLR_SKIP_PAIR)
        return kind == CLR_HIT_TRIANGLE && (index == skip_index || index == CLR_SKIP_PAIR - skip_kind);
#endif
    return kind == skip_kind && index == skip_index;
}

/* A hit inside the kernels; ClrHit is its float form in buffers. */
typedef struct {
    real t;    /* distance along the unit direction; +inf when kind is CLR_HIT_NONE */
    int kind;  /* CLR_HIT_* */
    int index; /* sphere or billboard index; -1 when kind is CLR_HIT_NONE */
} Hit;

/* Dot product written out, in a fixed order. The built-in dot() may be computed in another
 * order or with FMAs, which would make the scalar and 16-lane paths differ in the last bit. */
real dot3(real3 a, real3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

/* |p.x q.x| + |p.y q.y| + |p.z q.z|: the bound on the rounding of dot3(p, q). */
real abs_dot3(real3 p, real3 q)
{
    return fabs(p.x * q.x) + fabs(p.y * q.y) + fabs(p.z * q.z);
}

/* v / |v| with dot3, for the same reason. */
real3 unit3(real3 v)
{
    return v / sqrt(dot3(v, v));
}

/* Display byte for a colour channel: round(clamp(c, 0, 1) * 255), rounding halves up as
 * the host reference does (docs/scene-format.md, Conventions: Colour). */
uchar color_to_byte(float c)
{
    return (uchar)floor(clamp(c, 0.0f, 1.0f) * 255.0f + 0.5f);
}

/* Mirror direction of d about the unit normal n. */
real3 reflect_direction(real3 d, real3 n)
{
    return d - 2.0f * dot3(d, n) * n; /* dot3, not dot(): see surface_color() in shade.cl */
}

#endif /* CLR_COMMON_MATH_CL */
