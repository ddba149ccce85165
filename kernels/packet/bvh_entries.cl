/* Where a screen tile's packets enter the BVH (ClrSceneInfo::primary_bvh). Each of a tile's
 * 4x4 blocks walked the BVH from its root: of a packet's box tests on a million-triangle
 * terrain, about 30 of 68 were in the tree's top 12 levels, the same few boxes for every
 * block of the tile. The tile finds them once: it walks the tree level by level with the
 * pyramid of its rays (tile_frustum()), keeping each level's boxes that the pyramid meets, as
 * long as they number at most CLR_BVH_ENTRIES; its packets start their walks from the last
 * such level (docs/benchmarks.md, A tile's entries into the BVH).
 *
 * The pyramid reaches a pixel beyond the tile on every side, so it holds every ray of the
 * tile's pixels, samples included (their offsets lie within the pixel), however its planes
 * and the rays round; a box it leaves out holds nothing those rays can meet. The entries are
 * disjoint subtrees that hold every object the walk from the root could reach, so each lane
 * tests the objects it would have, and hits are ranked as ever (common/hit_order.cl). */
#ifndef CLR_PACKET_BVH_ENTRIES_CL
#define CLR_PACKET_BVH_ENTRIES_CL

#include "common/bvh_nodes.cl"
#include "common/math.cl"
#include "common/scene_params.cl"
#include "intersect.cl"
#include "packet/packet_types.cl"
#include "shared/clr_types.h"

#if CLR_FEATURE_BVH

/* The pyramid from the eye through a rectangle of the image: the points p with
 * dot(n, p - eye) >= 0 for the normal n of each of its four sides, (nx, ny, nz) a side a lane
 * (tested four at once, without a branch a side). */
typedef struct {
    real4 nx, ny, nz;
    real3 eye;
    real3 centre; /* the direction through the rectangle's centre */
} TileFrustum;

/* The pyramid of the rays through pixels [col_begin, col_end) x [row_begin, row_end), one
 * pixel wider on each side. The direction through image point (a, b) is F + a R + b U
 * (ClrCamera); the side through a = a0 is spanned by F + a0 R and U, and a direction's
 * product with (F + a0 R) x U is (a - a0) det(R, F, U): the sides' signs follow from that
 * determinant's, whatever the basis' handedness. */
TileFrustum tile_frustum(ClrCamera camera, int col_begin, int col_end, int row_begin, int row_end)
{
    real3 forward = convert_real3(camera.forward.xyz), right = convert_real3(camera.right.xyz);
    real3 up = convert_real3(camera.up.xyz);
    real a0 = 2.0f * (real)(col_begin - 1) / (real)camera.width - 1.0f;
    real a1 = 2.0f * (real)(col_end + 1) / (real)camera.width - 1.0f;
    real b0 = 1.0f - 2.0f * (real)(row_end + 1) / (real)camera.height; /* b falls as rows go down */
    real b1 = 1.0f - 2.0f * (real)(row_begin - 1) / (real)camera.height;
    real s = dot(right, cross(forward, up)) < 0.0f ? -1.0f : 1.0f;
    real3 side[4] = {s * cross(forward + a0 * right, up), -s * cross(forward + a1 * right, up),
                     -s * cross(forward + b0 * up, right), s * cross(forward + b1 * up, right)};
    /* Each side scaled to its largest component 1: only the signs of its products count, and a
     * lens near 180 degrees makes right and up about 1e12 long, whose products, against a box
     * 1e15 away, left float's range (+inf and -inf summed to NaN, and the box was left out). */
    for (int i = 0; i < 4; ++i)
        side[i] /= fmax(fmax(fabs(side[i].x), fabs(side[i].y)), fabs(side[i].z));
    TileFrustum f;
    f.nx = (real4)(side[0].x, side[1].x, side[2].x, side[3].x);
    f.ny = (real4)(side[0].y, side[1].y, side[2].y, side[3].y);
    f.nz = (real4)(side[0].z, side[1].z, side[2].z, side[3].z);
    f.eye = convert_real3(camera.eye.xyz);
    f.centre = forward + 0.5f * (a0 + a1) * right + 0.5f * (b0 + b1) * up;
    return f;
}

/* Whether `node`'s box has a point inside the pyramid by each side's test: its corner farthest
 * along each side's normal. (A box beside a corner of the pyramid may pass: an entry too many,
 * never one too few.) */
bool frustum_meets(const TileFrustum* f, __global const ClrBvhNode* node)
{
    real3 lower = convert_real3(node->lower.xyz) - f->eye, upper = convert_real3(node->upper.xyz) - f->eye;
    real4 x = select((real4)(lower.x), (real4)(upper.x), f->nx > 0.0f);
    real4 y = select((real4)(lower.y), (real4)(upper.y), f->ny > 0.0f);
    real4 z = select((real4)(lower.z), (real4)(upper.z), f->nz > 0.0f);
    real4 along = f->nx * x + f->ny * y + f->nz * z;
    return (along.x >= 0.0f) & (along.y >= 0.0f) & (along.z >= 0.0f) & (along.w >= 0.0f);
}

/* How far along `direction` the centre of `node`'s box lies from `origin`, doubled: which of
 * two children rays heading that way meet first. */
real centre_along(__global const ClrBvhNode* node, real3 origin, real3 direction)
{
    real3 doubled = convert_real3(node->lower.xyz) + convert_real3(node->upper.xyz) - 2.0f * origin;
    return doubled.x * direction.x + doubled.y * direction.y + doubled.z * direction.z;
}

/* The deepest level of the BVH (leaves kept as they are) whose boxes that `f` meets are at
 * most CLR_BVH_ENTRIES, into `entries`, each node's children nearer first along the pyramid's
 * centre: about the order a packet's own walk would take. */
void bvh_entries(const TileFrustum* f, BvhEntries* entries, CLR_SCENE_PARAMS)
{
    BvhEntries next;
    entries->count = 0;
    if (bvh_roots(info) > 0 && frustum_meets(f, &bvh_nodes[0]))
        entries->node[entries->count++] = 0;
    for (;;) {
        next.count = 0;
        bool deeper = false;
        for (int i = 0; i < entries->count; ++i) {
            __global const ClrBvhNode* node = &bvh_nodes[entries->node[i]];
            uint kept[2];
            int n = 0;
            if (bvh_count(node) > 0) {
                kept[n++] = entries->node[i];
            } else {
                deeper = true;
                __global const ClrBvhNode* left = &bvh_nodes[bvh_first(node)];
                bool left_first = centre_along(left, f->eye, f->centre) <= centre_along(left + 1, f->eye, f->centre);
                uint near = left_first ? bvh_first(node) : bvh_first(node) + 1;
                uint far = left_first ? bvh_first(node) + 1 : bvh_first(node);
                if (frustum_meets(f, &bvh_nodes[near]))
                    kept[n++] = near;
                if (frustum_meets(f, &bvh_nodes[far]))
                    kept[n++] = far;
            }
            if (next.count + n > CLR_BVH_ENTRIES)
                return; /* too many: the level before */
            for (int k = 0; k < n; ++k)
                next.node[next.count++] = kept[k];
        }
        if (!deeper)
            return;
        *entries = next;
    }
}

#endif /* CLR_FEATURE_BVH */

#endif /* CLR_PACKET_BVH_ENTRIES_CL */
