/* Stage 2: nearest-hit intersection against spheres and billboards. Primary, shadow and
 * reflection rays all go through intersect_scene(). */
#ifndef CLR_INTERSECT_CL
#define CLR_INTERSECT_CL

#include "common/hit_order.cl"
#include "common/math.cl"
#include "common/scene_items.cl"
#include "common/scene_params.cl"
#include "common/texture.cl"
#include "shared/clr_types.h"

/* Distance along the unit direction to the nearest intersection with t > 0, or +inf.
 * Float32-robust form (Ray Tracing Gems, ch. 7): the discriminant is computed from the
 * distance between the centre and the ray's closest point instead of b*b - c, which would
 * cancel catastrophically for small or distant spheres, and the two roots come from
 * q = b + sign(b) sqrt(discriminant) as c/q and q, so neither subtracts nearly equal values. */
real sphere_distance(float4 center_radius, real3 origin, real3 direction)
{
    real radius = center_radius.w;
    real3 oc = origin - convert_real3(center_radius.xyz);
    real b = -dot3(oc, direction);              /* t of the closest approach */
    real3 closest_offset = oc + b * direction; /* centre -> closest point on the ray */
    real discriminant = radius * radius - dot3(closest_offset, closest_offset);
    if (discriminant < 0.0f)
        return INFINITY;
    real c = dot3(oc, oc) - radius * radius;
    real q = b + copysign(sqrt(discriminant), b);
    if (q == 0.0f) /* tangent exactly at the origin */
        return INFINITY;
    real t0 = c / q;
    real t1 = q;
    real t_near = fmin(t0, t1);
    real t_far = fmax(t0, t1);
    if (t_near > 0.0f)
        return t_near;
    return t_far > 0.0f ? t_far : INFINITY; /* origin inside the sphere: the far side */
}

/* Billboard coordinates (a, b) of the point at distance t along the ray. Used both when
 * testing a hit and when shading it, so the alpha test and the colour read the same texel. */
real2 billboard_coords(__global const ClrBillboard* billboard, real3 origin, real3 direction, real t)
{
    real3 from_corner = (origin - convert_real3(billboard->corner.xyz)) + t * direction; /* P - UL */
    return (real2)(dot3(from_corner, convert_real3(billboard->dual_a.xyz)),
                   dot3(from_corner, convert_real3(billboard->dual_b.xyz)));
}

/* Distance along the ray to the billboard's plane if the ray meets the parallelogram there
 * at an opaque texel with 0 < t < t_max, else +inf. A ray parallel to the plane divides by
 * zero; the resulting inf or NaN fails the range test, so no special case is needed. */
real billboard_distance(__global const ClrBillboard* billboard, __global const uchar4* texels, real3 origin,
                        real3 direction, real t_max)
{
    real3 normal = convert_real3(billboard->normal.xyz);
    real t = dot3(convert_real3(billboard->corner.xyz) - origin, normal) / dot3(direction, normal);
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

#if CLR_FEATURE_BVH
/* Whether the ray can meet the box before t_max (slab test). A zero direction component is
 * replaced by a tiny one, so that no 0 * inf makes a NaN; the exit distance gets a small
 * allowance for rounding (the boxes themselves are rounded outwards on the host). */
bool box_reachable(__global const ClrBvhNode* node, real3 origin, real3 inverse, real t_max)
{
    real3 t0 = (convert_real3(node->lower.xyz) - origin) * inverse;
    real3 t1 = (convert_real3(node->upper.xyz) - origin) * inverse;
    real3 near = fmin(t0, t1), far = fmax(t0, t1);
    real enter = fmax(fmax(near.x, near.y), fmax(near.z, (real)0.0f));
    real leave = fmin(fmin(far.x, far.y), far.z) * (real)1.000001f;
    return enter <= leave && enter <= t_max;
}

real3 safe_inverse(real3 d)
{
    real3 tiny = copysign((real3)(1e-30f), d);
    return (real3)(1.0f) / select(d, tiny, fabs(d) < (real3)(1e-30f));
}

/* intersect_scene() through the BVH: the same answer, visiting only the boxes the ray meets
 * before its best hit so far. */
Hit intersect_bvh(real3 origin, real3 direction, real t_max, int skip_kind, int skip_index, CLR_SCENE_PARAMS)
{
    Hit hit;
    hit.t = t_max;
    hit.kind = CLR_HIT_NONE;
    hit.index = -1;
    real3 inverse = safe_inverse(direction);
    uint stack[CLR_BVH_STACK];
    int top = 0;
    if (info.sphere_count + info.billboard_count > 0)
        stack[top++] = 0;
    while (top > 0) {
        __global const ClrBvhNode* node = &bvh_nodes[stack[--top]];
        if (!box_reachable(node, origin, inverse, hit.t))
            continue;
        if (node->count == 0) {
            stack[top++] = node->first + 1;
            stack[top++] = node->first;
            continue;
        }
        for (uint k = node->first; k < node->first + node->count; ++k) {
            int kind = item_kind(bvh_items[k]);
            int index = item_index(bvh_items[k]);
            if (kind == skip_kind && index == skip_index)
                continue;
            real t = INFINITY;
#if CLR_FEATURE_BILLBOARDS
            if (kind == CLR_HIT_BILLBOARD)
                t = billboard_distance(&billboards[index], texels, origin, direction, INFINITY);
#endif
#if CLR_FEATURE_SPHERES
            if (kind == CLR_HIT_SPHERE)
                t = sphere_distance(spheres[index].center_radius, origin, direction);
#endif
            if (hit_beats(t, kind, index, hit)) { /* common/hit_order.cl */
                hit.t = t;
                hit.kind = kind;
                hit.index = index;
            }
        }
    }
    if (hit.kind == CLR_HIT_NONE)
        hit.t = INFINITY;
    return hit;
}
#endif

/* The nearest surface along the ray with 0 < t < t_max. The surface (skip_kind,
 * skip_index) is left out: a secondary ray leaves a convex surface on its outer side and
 * cannot meet it again, so excluding it is exact and needs no scale-dependent epsilon.
 * Without a BVH the loops visit spheres, then billboards, by index: the order that
 * common/hit_order.cl ranks ties by, so keeping the first of equal distances (t < hit.t)
 * already is that rule and needs no tie-break. */
Hit intersect_scene(real3 origin, real3 direction, real t_max, int skip_kind, int skip_index, CLR_SCENE_PARAMS)
{
#if CLR_FEATURE_BVH
    return intersect_bvh(origin, direction, t_max, skip_kind, skip_index, CLR_SCENE_ARGS);
#else
    Hit hit;
    hit.t = t_max;
    hit.kind = CLR_HIT_NONE;
    hit.index = -1;
#if CLR_FEATURE_SPHERES
    for (int i = 0; i < info.sphere_count; ++i) {
        if (skip_kind == CLR_HIT_SPHERE && skip_index == i)
            continue;
        real t = sphere_distance(spheres[i].center_radius, origin, direction);
        if (t < hit.t) {
            hit.t = t;
            hit.kind = CLR_HIT_SPHERE;
            hit.index = i;
        }
    }
#endif
#if CLR_FEATURE_BILLBOARDS
    for (int i = 0; i < info.billboard_count; ++i) {
        if (skip_kind == CLR_HIT_BILLBOARD && skip_index == i)
            continue;
        real t = billboard_distance(&billboards[i], texels, origin, direction, hit.t);
        if (t < hit.t) {
            hit.t = t;
            hit.kind = CLR_HIT_BILLBOARD;
            hit.index = i;
        }
    }
#endif
    if (hit.kind == CLR_HIT_NONE)
        hit.t = INFINITY;
    return hit;
#endif
}

/* The float form of a hit, for buffers. */
ClrHit device_hit(Hit hit)
{
    ClrHit out;
    out.t = (float)hit.t;
    out.kind = hit.kind;
    out.index = hit.index;
    out.pad0 = 0;
    return out;
}

#endif /* CLR_INTERSECT_CL */
