/* any() and all() of the 16 lanes of a comparison (each lane 0 or all ones, int16 or, with
 * CLR_FEATURE_DOUBLE, long16), for the packet loop's decisions. PoCL 3.1 computes the
 * built-ins on 16 lanes as a chain of eight extracts, tests and branches: with five of them
 * in the loop, a fifth of a small scene's frame (docs/benchmarks.md, Packet fixed costs).
 * Packed to a byte per lane, the 16 lanes are two 64-bit words, tested at once. Plain
 * vector operations, not Clang's __builtin_reduce_or(), which is as fast on PoCL but which
 * Oclgrind 21.10 evaluates wrongly. Only for comparison results: the built-ins test each
 * lane's sign bit, these its low byte, which for 0 and all ones is the same. */
#ifndef CLR_PACKET_LANE_MASKS_CL
#define CLR_PACKET_LANE_MASKS_CL

#include "packet/packet_types.cl"

/* Whether any, or all, of 16 lanes packed to a byte each (0 or 0xff) are set. */
CLR_PACKET_INLINE int any_lane_bytes16(char16 lanes)
{
    ulong2 words = as_ulong2(lanes);
    return (words.x | words.y) != 0ul;
}

CLR_PACKET_INLINE int all_lane_bytes16(char16 lanes)
{
    ulong2 words = as_ulong2(lanes);
    return (words.x & words.y) == ~0ul;
}

/* any() and all() of a comparison's 16 lanes. */
#define any_lanes16(comparison) any_lane_bytes16(convert_char16(comparison))
#define all_lanes16(comparison) all_lane_bytes16(convert_char16(comparison))

#endif /* CLR_PACKET_LANE_MASKS_CL */
