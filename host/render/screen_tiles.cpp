#include "render/screen_tiles.h"

#include <algorithm>

#include "core/parallel_for.h"
#include "core/usable_cpus.h"
#include "kinds/kinds.h"
#include "render/object_bounds.h"
#include "render/pixel_centres.h"
#include "render/scene_item.h"
#include "render/tile_lists.h"

namespace clr {
namespace {

// Pixel rows first..last, packed as the kernels read them (ScreenTiles::rows).
std::uint32_t pack_rows(int first, int last) { return static_cast<std::uint32_t>(first) << 16 | static_cast<std::uint32_t>(last); }

// How far outside an object's bounds a pixel centre may lie and still be listed. With one
// sample per pixel its ray passes through the centre; with several, anywhere in the pixel,
// up to half a pixel from it. On top, a quarter of a pixel for rounding: thousands of times
// what the kernels' float rays and positions can move a silhouette (about 1e-4 pixel at 1920
// columns, 0.04 for a sphere of radius 1e6 a unit away). The margin had been one to two
// pixels: every row of a sphere a few pixels across tested it about twice as often as it
// could be seen (docs/benchmarks.md, Packet fixed costs).
double pixel_margin(int samples) { return (samples > 1 ? 0.5 : 0.0) + 0.25; }

// The tiles an object with `bounds` may cover, and its pixel rows: those whose pixel centres
// (the integers) lie within `margin` pixels of the bounds.
bool tile_range(const PixelBounds& b, const ScreenTiles& tiles, int width, int height, double margin, TileSpan& span) {
    if (!b.in_front) return false;  // behind the eye or outside the view: trees behind the camera in a forest
    if (b.whole_screen) {
        span.first_column = 0;
        span.last_column = tiles.tiles_x - 1;
        span.first_row = 0;
        span.last_row = tiles.tiles_y - 1;
        span.rows = pack_rows(0, height - 1);
        return true;
    }
    const double col_min = b.col_min - margin, col_max = b.col_max + margin;
    const double row_min = b.row_min - margin, row_max = b.row_max + margin;
    if (col_max < 0 || row_max < 0 || col_min > width - 1 || row_min > height - 1) return false;
    const int first_row = first_pixel_from(row_min), last_row = last_pixel_to(row_max, height);
    span.first_column = first_pixel_from(col_min) / kClrTileSize;
    span.last_column = last_pixel_to(col_max, width) / kClrTileSize;
    span.first_row = first_row / kClrTileSize;
    span.last_row = last_row / kClrTileSize;
    span.rows = pack_rows(first_row, last_row);
    return true;
}

// Frames with this many objects bin on every usable core: below, handing the work to other
// threads costs more than it saves (a course frame bins five objects in microseconds).
constexpr std::size_t kParallelFrom = 16384;
// Objects per task while placing.
constexpr std::size_t kPlaceChunk = 4096;

// Object `index` of `Kind` (kinds/kinds.h) as the tiles list it; false when no tile does.
template <typename Kind>
bool place(const FrameGeometry& frame, std::size_t index, const ObjectBounds& bounds, const ScreenTiles& tiles,
           const FrameCamera& camera, TileSpan& span) {
    const auto& object = Kind::object(frame, index);
    const Vec3 object_origin = Kind::origin(frame, index);
    const PixelBounds pixels = Kind::pixel_bounds(bounds, object, object_origin);
    if (!tile_range(pixels, tiles, camera.width, camera.height, pixel_margin(camera.samples), span)) return false;
    span.item = scene_item(Kind::kHit, index);
    // Stored slightly low: a float32 hit distance may fall a few ulps short of the true one,
    // and the kernel must never skip an object that its float ray does hit first.
    span.nearest = static_cast<float>(Kind::least_distance(bounds, object, object_origin) * (1 - 1e-5));
    return true;
}

// Objects [begin, end) of the frame (kind by kind, kinds/kinds.h) that some tile lists, in
// the frame's order.
void place_range(const FrameGeometry& frame, std::size_t begin, std::size_t end, const ObjectBounds& bounds,
                 const ScreenTiles& tiles, const FrameCamera& camera, std::vector<TileSpan>& placed) {
    std::size_t kind_begin = 0;
    for_each_bounded_kind([&](auto kind) {
        using Kind = decltype(kind);
        const std::size_t kind_end = kind_begin + Kind::count(frame);
        TileSpan span;
        for (std::size_t index = std::max(begin, kind_begin); index < std::min(end, kind_end); ++index)
            if (place<Kind>(frame, index - kind_begin, bounds, tiles, camera, span)) placed.push_back(span);
        kind_begin = kind_end;
    });
}

// How many tiles across and down `camera`'s frame has.
void size_tiles(const FrameCamera& camera, ScreenTiles& tiles) {
    tiles.tiles_x = (camera.width + kClrTileSize - 1) / kClrTileSize;
    tiles.tiles_y = (camera.height + kClrTileSize - 1) / kClrTileSize;
}

}  // namespace

ScreenTiles bin_screen_tiles(const FrameGeometry& frame, const FrameCamera& camera) {
    ScreenTiles tiles;
    ScreenTileBinner().bin(frame, camera, tiles);
    return tiles;
}

void leave_tiles_unlisted(const FrameCamera& camera, ScreenTiles& tiles) {
    size_tiles(camera, tiles);
    tiles.offsets.assign(static_cast<std::size_t>(tiles.tiles_x) * tiles.tiles_y + 1, 0);
    tiles.items.clear();
    tiles.nearest.clear();
    tiles.rows.clear();
}

void ScreenTileBinner::bin(const FrameGeometry& frame, const FrameCamera& camera, ScreenTiles& tiles) {
    size_tiles(camera, tiles);
    const std::size_t objects = frame.object_count();
    const std::size_t threads = objects >= kParallelFrom ? static_cast<std::size_t>(usable_cpu_count()) : 1;
    // The objects that some tile lists, in the frame's order: chunks of objects placed on
    // `threads` threads, each into a list of its own, joined in order.
    const ObjectBounds bounds(camera);
    placed_.clear();
    if (objects <= kPlaceChunk) {  // a small frame: no copy
        place_range(frame, 0, objects, bounds, tiles, camera, placed_);
    } else {
        chunks_.resize((objects + kPlaceChunk - 1) / kPlaceChunk);
        parallel_for(chunks_.size(), threads, [&](std::size_t chunk) {
            chunks_[chunk].clear();
            place_range(frame, chunk * kPlaceChunk, std::min(objects, (chunk + 1) * kPlaceChunk), bounds, tiles,
                        camera, chunks_[chunk]);
        });
        for (const std::vector<TileSpan>& chunk : chunks_) placed_.insert(placed_.end(), chunk.begin(), chunk.end());
    }
    lister_.list(placed_, threads, tiles);
}

}  // namespace clr
