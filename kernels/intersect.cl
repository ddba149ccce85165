/* Stage 2: nearest-hit intersection against spheres and billboards. Primary, shadow and
 * reflection rays all go through intersect_scene(). */

/* The scene buffers every stage reads, as kernel and function parameters. Counts stay
 * run-time values (ClrSceneInfo), so one compiled program serves every scene of a kind. */
#define CLR_SCENE_PARAMS                                                                      \
    __global const ClrSphere *spheres, __global const ClrBillboard *billboards,              \
        __global const uchar4 *texels, ClrSceneInfo info
#define CLR_SCENE_ARGS spheres, billboards, texels, info

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
    /* A texel with alpha below 255 is a hole: the ray goes on as if nothing were here. */
    if ((billboard->flags & CLR_SURFACE_HOLES) && billboard_texel(billboard, texels, ab.x, ab.y).w < 255)
        return INFINITY;
#endif
    return t;
}

/* The nearest surface along the ray with 0 < t < t_max. The surface (skip_kind,
 * skip_index) is left out: a secondary ray leaves a convex surface on its outer side and
 * cannot meet it again, so excluding it is exact and needs no scale-dependent epsilon. */
Hit intersect_scene(real3 origin, real3 direction, real t_max, int skip_kind, int skip_index, CLR_SCENE_PARAMS)
{
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

/* One work-item per ray: writes the nearest hit of rays[i] to hits[i], for i < ray_count. */
__kernel void intersect(__global const ClrRay* rays, int ray_count, CLR_SCENE_PARAMS, __global ClrHit* hits)
{
    int i = get_global_id(0);
    if (i >= ray_count)
        return;
    Hit hit = intersect_scene(convert_real3(rays[i].origin.xyz), convert_real3(rays[i].direction.xyz), INFINITY,
                              CLR_HIT_NONE, -1, CLR_SCENE_ARGS);
    hits[i] = device_hit(hit);
}
