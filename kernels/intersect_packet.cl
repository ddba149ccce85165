/* Primary rays 16 at a time: the 16 pixels of one row of a screen tile share the eye as
 * origin and the tile's object list, so each object is tested against all 16 rays with
 * 16-wide vector arithmetic (one AVX-512 instruction per operation on CPUs). PoCL does not
 * vectorise the scalar loop by itself (the running nearest hit defeats it), hence explicit
 * float16. Every formula is the scalar one of intersect.cl, operation for operation, so each
 * lane computes the same bits as the scalar path would (FP_CONTRACT is off, see math.cl). */

typedef struct {
    float16 x, y, z;
} Directions16;

/* The 16 lanes' column offsets within the packet. */
#define CLR_LANES ((int16)(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15))

/* camera_ray_through() for pixels (col0 .. col0 + 15, row), at offsets (ox, oy) in them. */
Directions16 camera_rays16(ClrCamera camera, int col0, int row, float16 ox, float16 oy)
{
    float16 col = convert_float16((int16)(col0) + CLR_LANES);
    float16 sx = 2.0f * (col + ox) / (float)camera.width - 1.0f;
    float16 sy = 1.0f - 2.0f * ((float)row + oy) / (float)camera.height;
    Directions16 d;
    d.x = camera.forward.x + sx * camera.right.x + sy * camera.up.x;  /* as camera_ray_through() */
    d.y = camera.forward.y + sx * camera.right.y + sy * camera.up.y;
    d.z = camera.forward.z + sx * camera.right.z + sy * camera.up.z;
    float16 length = sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    d.x = d.x / length;
    d.y = d.y / length;
    d.z = d.z / length;
    return d;
}

float16 dot16(float3 a, Directions16 d)
{
    return a.x * d.x + a.y * d.y + a.z * d.z;
}

/* sphere_distance() for 16 rays from one origin. */
float16 sphere_distance16(float4 center_radius, float3 origin, Directions16 d)
{
    float radius = center_radius.w;
    float3 oc = origin - center_radius.xyz;
    float16 b = -dot16(oc, d);
    float16 cx = oc.x + b * d.x, cy = oc.y + b * d.y, cz = oc.z + b * d.z;
    float16 discriminant = radius * radius - (cx * cx + cy * cy + cz * cz);
    if (!any(discriminant >= 0.0f))
        return (float16)(INFINITY); /* all 16 rays miss: skip the square root and division */
    float c = dot3(oc, oc) - radius * radius;
    float16 q = b + copysign(sqrt(discriminant), b);
    float16 t0 = c / q;
    float16 t1 = q;
    float16 t_near = fmin(t0, t1);
    float16 t_far = fmax(t0, t1);
    float16 t = select(select((float16)(INFINITY), t_far, t_far > 0.0f), t_near, t_near > 0.0f);
    return select(t, (float16)(INFINITY), discriminant < 0.0f || q == 0.0f);
}

/* billboard_distance() for 16 rays from one origin (t_max = infinity). */
float16 billboard_distance16(__global const ClrBillboard* billboard, __global const uchar4* texels, float3 origin,
                             Directions16 d)
{
    float3 normal = billboard->normal.xyz;
    float16 t = dot3(billboard->corner.xyz - origin, normal) / dot16(normal, d);
    float3 origin_from_corner = origin - billboard->corner.xyz;
    float16 fx = origin_from_corner.x + t * d.x;
    float16 fy = origin_from_corner.y + t * d.y;
    float16 fz = origin_from_corner.z + t * d.z;
    float3 da = billboard->dual_a.xyz, db = billboard->dual_b.xyz;
    float16 a = fx * da.x + fy * da.y + fz * da.z;
    float16 b = fx * db.x + fy * db.y + fz * db.z;
    int16 inside = t > 0.0f && t < INFINITY && a >= 0.0f && a <= 1.0f && b >= 0.0f && b <= 1.0f;
#if CLR_FEATURE_ALPHA
    if ((billboard->flags & CLR_SURFACE_HOLES) && any(inside)) {
        /* Texel lookups are gathers: done lane by lane, only where the ray is inside. */
        float as[16], bs[16];
        int keep[16];
        vstore16(a, 0, as);
        vstore16(b, 0, bs);
        vstore16(inside, 0, keep);
        for (int lane = 0; lane < 16; ++lane)
            if (keep[lane] && billboard_texel(billboard, texels, as[lane], bs[lane]).w < 255)
                keep[lane] = 0;
        inside = vload16(0, keep);
    }
#endif
    return select((float16)(INFINITY), t, inside);
}

/* The nearest hits of 16 primary rays among the objects binned to their screen tile
 * (items[first] .. items[end - 1], nearest first; see host/render/screen_tiles.h). The loop
 * ends once every lane's hit is nearer than every object left (item_nearest holds a lower
 * bound on each object's hit distance). Hits are compared by (t, kind, index): nearer, or as
 * near and first in intersect_scene()'s order (spheres, then billboards, by index), so the
 * visiting order does not matter and the answer is intersect_scene()'s, ties included. */
void intersect_tile16(float3 origin, Directions16 d, __global const uint* items, __global const float* item_nearest,
                      uint first, uint end, CLR_SCENE_PARAMS, float16* best_t, int16* best_kind, int16* best_index)
{
    *best_t = (float16)(INFINITY);
    *best_kind = (int16)(CLR_HIT_NONE);
    *best_index = (int16)(-1);
    for (uint k = first; k < end; ++k) {
        if (all(*best_t < item_nearest[k]))
            break;
        uint item = items[k];
        int index = (int)(item & ~CLR_TILE_BILLBOARD);
        int kind = (item & CLR_TILE_BILLBOARD) ? CLR_HIT_BILLBOARD : CLR_HIT_SPHERE;
        float16 t = (float16)(INFINITY);
#if CLR_FEATURE_BILLBOARDS
        if (kind == CLR_HIT_BILLBOARD)
            t = billboard_distance16(&billboards[index], texels, origin, d);
#endif
#if CLR_FEATURE_SPHERES
        if (kind == CLR_HIT_SPHERE)
            t = sphere_distance16(spheres[index].center_radius, origin, d);
#endif
        int16 beats = t < *best_t ||
                      (t == *best_t && t < INFINITY &&
                       (kind < *best_kind || (kind == *best_kind && index < *best_index)));
        *best_t = select(*best_t, t, beats);
        *best_kind = select(*best_kind, (int16)(kind), beats);
        *best_index = select(*best_index, (int16)(index), beats);
    }
}
