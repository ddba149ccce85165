/* A packet's 16 lanes one at a time: their hits, directions and colours in private arrays,
 * for the shading steps that go lane by lane (packet/render_row16.cl, packet/sunlit16.cl). */
#ifndef CLR_PACKET_LANES16_CL
#define CLR_PACKET_LANES16_CL

#include "common/math.cl"
#include "packet/packet_types.cl"

/* 16 rays' hits and directions, and their colours, lane by lane in private arrays: what the
 * shading steps that go one lane at a time read and write. */
typedef struct {
    real t[16], x[16], y[16], z[16];
    int kind[16], index[16];
    float r[16], g[16], b[16];
} Lanes16;

/* The lanes of `hits` and `d`, with the colours of `flat` when given. */
CLR_PACKET_INLINE void unpack_lanes16(Directions16 d, Hits16 hits, const Colors16* flat, Lanes16* lanes)
{
    if (flat) {
        vstore16(flat->r, 0, lanes->r);
        vstore16(flat->g, 0, lanes->g);
        vstore16(flat->b, 0, lanes->b);
    }
    vstore16(hits.t, 0, lanes->t);
    vstore16(hits.kind, 0, lanes->kind);
    vstore16(hits.index, 0, lanes->index);
    vstore16(d.x, 0, lanes->x);
    vstore16(d.y, 0, lanes->y);
    vstore16(d.z, 0, lanes->z);
}

CLR_PACKET_INLINE Colors16 lane_colors16(const Lanes16* lanes)
{
    Colors16 out;
    out.r = vload16(0, lanes->r);
    out.g = vload16(0, lanes->g);
    out.b = vload16(0, lanes->b);
    return out;
}

CLR_PACKET_INLINE void set_lane_color16(Lanes16* lanes, int lane, float3 color)
{
    lanes->r[lane] = color.x;
    lanes->g[lane] = color.y;
    lanes->b[lane] = color.z;
}

#endif /* CLR_PACKET_LANES16_CL */
