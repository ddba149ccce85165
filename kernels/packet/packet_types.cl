/* What the 16-ray packet code passes around: primary rays 16 at a time, one per lane, share
 * the eye as origin and differ in direction. */
#ifndef CLR_PACKET_TYPES_CL
#define CLR_PACKET_TYPES_CL

#include "common/math.cl"

/* The packet functions are inlined into render_packets: called, they pass their 16-lane
 * vectors and results through the stack. */
#define CLR_PACKET_INLINE __attribute__((always_inline))

/* The pixels of a packet's 16 lanes, lane l at (col[l], row[l]): 16 of one row, whose screen
 * tile's list culls objects by that row, or, where packets walk the BVH (info.primary_bvh), a
 * 4x4 block, whose rays spread less and so reach fewer boxes. */
typedef struct {
    int16 col, row;
} LanePixels16;

/* The 16 lanes' offsets within a packet: 0 .. 15. */
#define CLR_LANES ((int16)(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15))

/* Pixels col0 .. col0 + 15 of `row`. */
CLR_PACKET_INLINE LanePixels16 row_pixels16(int col0, int row)
{
    LanePixels16 pixels = {(int16)(col0) + CLR_LANES, (int16)(row)};
    return pixels;
}

/* The 4x4 block from (col0, row0), row by row. */
CLR_PACKET_INLINE LanePixels16 block_pixels16(int col0, int row0)
{
    LanePixels16 pixels = {(int16)(col0) + (CLR_LANES & (int16)(3)), (int16)(row0) + (CLR_LANES >> (int16)(2))};
    return pixels;
}

/* The 16 rays' unit directions. */
typedef struct {
    real16 x, y, z;
} Directions16;

/* 16 points, one per lane: the origins of rays that do not all start at the eye. */
typedef struct {
    real16 x, y, z;
} Points16;

/* The 16 rays' nearest hits so far, lane by lane as in Hit. */
typedef struct {
    real16 t;
    int16 kind;
    int16 index;
} Hits16;

/* 16 colours (or sums of colours), one per lane. */
typedef struct {
    float16 r, g, b;
} Colors16;

/* dot3() of a vector with each of 16 directions. */
CLR_PACKET_INLINE real16 dot16(real3 a, Directions16 d)
{
    return a.x * d.x + a.y * d.y + a.z * d.z;
}

/* One colour in all 16 lanes: a kind whose surface has a single colour. */
CLR_PACKET_INLINE Colors16 uniform_colors16(float3 color)
{
    Colors16 out;
    out.r = (float16)(color.x);
    out.g = (float16)(color.y);
    out.b = (float16)(color.z);
    return out;
}

/* Where a tile's packets enter the BVH, where they walk it (packet/bvh_entries.cl): the roots
 * of disjoint subtrees that hold every object the tile's rays may meet, nearest first. */
#define CLR_BVH_ENTRIES 16
typedef struct {
    uint node[CLR_BVH_ENTRIES];
    int count;
} BvhEntries;

/* The objects binned to one screen tile (host/render/screen_tiles.h), entries first .. end - 1
 * of its lists: items[k] (common/scene_items.cl), nearest first; nearest[k], a lower bound on
 * the object's hit distance; rows[k], the pixel rows it may cover (first << 16 | last). */
typedef struct {
    __global const uint* items;
    __global const float* nearest;
    __global const uint* rows;
    uint first, end;
    const BvhEntries* entries; /* where packets walk the BVH instead (info.primary_bvh) */
} TileItems;

#endif /* CLR_PACKET_TYPES_CL */
