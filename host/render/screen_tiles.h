// Screen-space culling for primary rays. Each frame, every object's projection is bounded
// conservatively and the object is listed in the 16x16-pixel tiles it may cover, nearest
// first. A pixel then tests only its tile's objects, and stops as soon as its best hit is
// nearer than every object left: empty screen regions cost almost nothing, and pixels test
// only the objects that can cover them. Secondary rays (shadows, mirrors) do not use this.
#pragma once

#include <cstdint>
#include <vector>

#include "render/frame_camera.h"
#include "render/frame_geometry.h"
#include "render/tile_lists.h"
#include "shared/clr_types.h"

namespace clr {

struct ScreenTiles {
    int tiles_x = 0, tiles_y = 0;
    std::vector<std::uint32_t> offsets;  // tile t's items are items[offsets[t] .. offsets[t+1])
    std::vector<std::uint32_t> items;    // scene items (render/scene_item.h)
    std::vector<float> nearest;          // per item: a lower bound on any hit distance
    // Per item: the pixel rows it may cover, first << 16 | last. A row of a tile skips the
    // tile's objects that cannot reach it: small distant objects cover few of its 16 rows.
    std::vector<std::uint32_t> rows;
};

// Bins the frame's objects for the view of `camera`, whose float-rounded values are those the
// kernels get, so that the projection matches their rays.
ScreenTiles bin_screen_tiles(const FrameGeometry& frame, const FrameCamera& camera);

// The tiles of `camera`'s frame, each with an empty list, for packets that walk the BVH
// instead (ClrSceneInfo::primary_bvh); reuses the arrays of `tiles`.
void leave_tiles_unlisted(const FrameCamera& camera, ScreenTiles& tiles);

// Bins frame after frame with the same working arrays, and into the same lists: a renderer
// bins every frame of a moving camera, and 100,000 spheres take about 15 MB of arrays, which
// fresh from the system cost a page fault and a zero fill per 4 KB (docs/benchmarks.md).
class ScreenTileBinner {
public:
    // Replaces `tiles` with the lists of bin_screen_tiles(), reusing its arrays.
    void bin(const FrameGeometry& frame, const FrameCamera& camera, ScreenTiles& tiles);

private:
    std::vector<std::vector<TileSpan>> chunks_;  // the objects placed, chunk by chunk
    std::vector<TileSpan> placed_;               // all of them, in the frame's order
    TileLister lister_;
};

}  // namespace clr
