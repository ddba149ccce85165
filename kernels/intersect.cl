/* Stage 2: nearest-hit intersection against every kind of object (kinds/kinds.cl). Primary,
 * shadow and reflection rays all go through intersect_scene(). */
#ifndef CLR_INTERSECT_CL
#define CLR_INTERSECT_CL

#include "common/bvh_nodes.cl"
#include "common/hit_order.cl"
#include "common/math.cl"
#include "common/scene_items.cl"
#include "common/scene_params.cl"
#include "kinds/kinds.cl"
#include "shared/clr_types.h"

/* Planes lie in no BVH and no screen tile (kinds/plane.cl): a ray that searched the culled
 * objects tests every plane too, but (skip_kind, skip_index), keeping `hit` where it wins. */
void nearest_plane(real3 origin, real3 direction, int skip_kind, int skip_index, Hit* hit, CLR_SCENE_PARAMS)
{
#if CLR_FEATURE_PLANES
    for (int i = 0; i < info.plane_count; ++i) {
        if (skip_kind == CLR_HIT_PLANE && skip_index == i)
            continue;
        real t = plane_hit_distance(i, origin, direction, INFINITY, CLR_SCENE_ARGS);
        if (hit_beats(t, CLR_HIT_PLANE, i, *hit)) {
            hit->t = t;
            hit->kind = CLR_HIT_PLANE;
            hit->index = i;
        }
    }
#endif
}

#if CLR_FEATURE_BVH
/* The larger and the smaller of two numbers that are not NaN. fmax() and fmin() must also
 * pass over a NaN, which costs a comparison and a blend per call (a third of a shadow ray's
 * time went to the box test); with no NaN about, the result is the same. */
real larger(real a, real b) { return a > b ? a : b; }
real smaller(real a, real b) { return a < b ? a : b; }

/* Whether the ray can meet the box before t_max (slab test). A zero direction component is
 * replaced by a tiny one, so that no 0 * inf makes a NaN (the products are finite or infinite,
 * never NaN: larger() and smaller() suffice); the exit distance gets a small allowance for
 * rounding (the boxes themselves are rounded outwards on the host). */
bool box_reachable(__global const ClrBvhNode* node, real3 origin, real3 inverse, real t_max)
{
    real3 t0 = (convert_real3(node->lower.xyz) - origin) * inverse;
    real3 t1 = (convert_real3(node->upper.xyz) - origin) * inverse;
    real enter = larger(larger(smaller(t0.x, t1.x), smaller(t0.y, t1.y)), larger(smaller(t0.z, t1.z), (real)0.0f));
    real leave = smaller(smaller(larger(t0.x, t1.x), larger(t0.y, t1.y)), larger(t0.z, t1.z)) * (real)1.000001f;
    return enter <= leave && enter <= t_max;
}

/* How many entries a walk's stack starts with: the root (node 0), where the BVH holds any
 * object. */
int bvh_roots(ClrSceneInfo info)
{
    return info.sphere_count + info.billboard_count + info.triangle_count > 0 ? 1 : 0;
}

real3 safe_inverse(real3 d)
{
    real3 tiny = copysign((real3)(1e-30f), d);
    return (real3)(1.0f) / select(d, tiny, fabs(d) < (real3)(1e-30f));
}

/* intersect_scene() through the BVH: the same answer, visiting only the boxes the ray meets
 * before its best hit so far. With `first_hit`, the first surface found within t_max instead
 * of the nearest (occluded()). */
Hit intersect_bvh(real3 origin, real3 direction, real t_max, int skip_kind, int skip_index, int first_hit,
                  CLR_SCENE_PARAMS)
{
    Hit hit;
    hit.t = t_max;
    hit.kind = CLR_HIT_NONE;
    hit.index = -1;
    real3 inverse = safe_inverse(direction);
    uint stack[CLR_BVH_STACK];
    stack[0] = 0;
    int top = bvh_roots(info);
    while (top > 0) {
        __global const ClrBvhNode* node = &bvh_nodes[stack[--top]];
        if (!box_reachable(node, origin, inverse, hit.t))
            continue;
        if (bvh_count(node) == 0) {
            stack[top++] = bvh_first(node) + 1;
            stack[top++] = bvh_first(node);
            continue;
        }
        for (uint k = bvh_first(node), end = k + bvh_count(node); k < end; ++k) {
            int kind = item_kind(bvh_items[k]);
            int index = item_index(bvh_items[k]);
            if (skips_surface(kind, index, skip_kind, skip_index))
                continue;
            /* Not t_max = hit.t: an equally near hit may still win on (kind, index). */
            real t = kind_hit_distance(kind, index, origin, direction, INFINITY, CLR_SCENE_ARGS);
            if (hit_beats(t, kind, index, hit)) { /* common/hit_order.cl */
                hit.t = t;
                hit.kind = kind;
                hit.index = index;
                if (first_hit)
                    return hit;
            }
        }
    }
    nearest_plane(origin, direction, skip_kind, skip_index, &hit, CLR_SCENE_ARGS);
    if (hit.kind == CLR_HIT_NONE)
        hit.t = INFINITY;
    return hit;
}
#endif

/* The nearest surface along the ray with 0 < t < t_max. The surface (skip_kind,
 * skip_index) is left out: a secondary ray leaves a convex surface on its outer side and
 * cannot meet it again, so excluding it is exact and needs no scale-dependent epsilon.
 * Without a BVH every object is tested (nearest_of_all_kinds()). */
Hit intersect_scene(real3 origin, real3 direction, real t_max, int skip_kind, int skip_index, CLR_SCENE_PARAMS)
{
#if CLR_FEATURE_BVH
    return intersect_bvh(origin, direction, t_max, skip_kind, skip_index, 0, CLR_SCENE_ARGS);
#else
    Hit hit = nearest_of_all_kinds(origin, direction, t_max, skip_kind, skip_index, 0, CLR_SCENE_ARGS);
    if (hit.kind == CLR_HIT_NONE)
        hit.t = INFINITY;
    return hit;
#endif
}

/* Whether a surface other than (skip_kind, skip_index) lies on the ray with 0 < t < t_max:
 * a shadow ray's question. The answer is intersect_scene()'s (a hit or none), found at the
 * first surface within t_max instead of the nearest, so that a shadow ray through a mesh
 * stops at the first triangle it meets. */
bool occluded(real3 origin, real3 direction, real t_max, int skip_kind, int skip_index, CLR_SCENE_PARAMS)
{
#if CLR_FEATURE_BVH
    Hit hit = intersect_bvh(origin, direction, t_max, skip_kind, skip_index, 1, CLR_SCENE_ARGS);
#else
    Hit hit = nearest_of_all_kinds(origin, direction, t_max, skip_kind, skip_index, 1, CLR_SCENE_ARGS);
#endif
    return hit.kind != CLR_HIT_NONE;
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
