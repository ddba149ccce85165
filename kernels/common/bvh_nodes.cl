/* A BVH node's two integers, which the host stores (plus CLR_BVH_WORD_BIAS) as the bits of its
 * boxes' w words so that a node is 32 bytes and two siblings share a cache line (ClrBvhNode,
 * shared/clr_types.h). */
#ifndef CLR_COMMON_BVH_NODES_CL
#define CLR_COMMON_BVH_NODES_CL

#include "shared/clr_types.h"

/* Inner node: its left child's index (the right child's is one more). Leaf: its first item. */
uint bvh_first(__global const ClrBvhNode* node)
{
    return as_uint(node->lower.w) - CLR_BVH_WORD_BIAS;
}

/* Leaf: how many items it holds. Inner node: 0. */
uint bvh_count(__global const ClrBvhNode* node)
{
    return as_uint(node->upper.w) - CLR_BVH_WORD_BIAS;
}

#endif /* CLR_COMMON_BVH_NODES_CL */
