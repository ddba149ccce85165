#include "render/screen_tiles.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "core/radix_sort.h"
#include "render/object_bounds.h"

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
bool tile_range(const PixelBounds& b, const ScreenTiles& tiles, int width, int height, double margin,
                std::array<int, 4>& range, std::uint32_t& rows) {
    if (!b.in_front) return false;  // behind the eye or outside the view: trees behind the camera in a forest
    if (b.whole_screen) {
        range = {0, tiles.tiles_x - 1, 0, tiles.tiles_y - 1};
        rows = pack_rows(0, height - 1);
        return true;
    }
    double col_min = std::ceil(b.col_min - margin), col_max = std::floor(b.col_max + margin);
    double row_min = std::ceil(b.row_min - margin), row_max = std::floor(b.row_max + margin);
    if (col_max < 0 || row_max < 0 || col_min > width - 1 || row_min > height - 1) return false;
    auto pixel_of = [](double pixel, int count) { return static_cast<int>(std::clamp(pixel, 0.0, double(count) - 1)); };
    range = {pixel_of(col_min, width) / kClrTileSize, pixel_of(col_max, width) / kClrTileSize,
             pixel_of(row_min, height) / kClrTileSize, pixel_of(row_max, height) / kClrTileSize};
    rows = pack_rows(pixel_of(row_min, height), pixel_of(row_max, height));
    return true;
}

// An object that some tile lists.
struct Placed {
    std::uint32_t item;
    float nearest;  // ScreenTiles::nearest
    std::uint32_t rows;
    std::array<int, 4> range;  // tile columns first, last, tile rows first, last
};

// The objects of a frame that some tile lists, and the order in which the tiles list them.
class Placement {
public:
    Placement(const ScreenTiles& tiles, const FrameCamera& camera) : tiles_(tiles), camera_(camera) {}

    void add(std::uint32_t item, double nearest, const PixelBounds& bounds) {
        std::array<int, 4> range;
        std::uint32_t rows;
        if (!tile_range(bounds, tiles_, camera_.width, camera_.height, pixel_margin(camera_.samples), range, rows))
            return;
        // Stored slightly low: a float32 hit distance may fall a few ulps short of the true
        // one, and the kernel must never skip an object that its float ray does hit first.
        const float bound = static_cast<float>(nearest * (1 - 1e-5));
        // The order key: the bound's bits (a float >= 0 orders as its bits do), then the
        // object's place in the frame, so that every tile's list is nearest first in a
        // deterministic order.
        std::uint32_t bits;
        std::memcpy(&bits, &bound, sizeof bits);
        order_.push_back(static_cast<std::uint64_t>(bits) << 32 | placed_.size());
        placed_.push_back({item, bound, rows, range});
    }

    // The placed objects, nearest first.
    std::vector<Placed> nearest_first() {
        radix_sort(order_);
        std::vector<Placed> sorted;
        sorted.reserve(placed_.size());
        for (std::uint64_t key : order_) sorted.push_back(placed_[static_cast<std::uint32_t>(key)]);
        return sorted;
    }

private:
    const ScreenTiles& tiles_;
    const FrameCamera& camera_;
    std::vector<Placed> placed_;
    std::vector<std::uint64_t> order_;
};

}  // namespace

ScreenTiles bin_screen_tiles(const FrameGeometry& frame, const FrameCamera& camera) {
    ScreenTiles tiles;
    tiles.tiles_x = (camera.width + kClrTileSize - 1) / kClrTileSize;
    tiles.tiles_y = (camera.height + kClrTileSize - 1) / kClrTileSize;
    const ObjectBounds bounds(camera);
    Placement placement(tiles, camera);
    for (std::size_t i = 0; i < frame.spheres().size(); ++i) {
        const Sphere& sphere = frame.spheres()[i];
        placement.add(static_cast<std::uint32_t>(i), bounds.sphere_distance(sphere), bounds.sphere(sphere));
    }
    for (std::size_t i = 0; i < frame.billboard_count(); ++i) {
        const Billboard& billboard = frame.billboard(i);
        placement.add(static_cast<std::uint32_t>(i) | CLR_TILE_BILLBOARD, bounds.billboard_distance(billboard),
                      bounds.billboard(billboard));
    }
    // Two passes over flat arrays (count per tile, then fill nearest first), without a list
    // per tile: a frame bins anew, and a vector per tile (thousands at 1080p) would be
    // allocated and freed every frame (docs/benchmarks.md).
    const std::vector<Placed> sorted = placement.nearest_first();
    std::vector<std::uint32_t> counts(static_cast<std::size_t>(tiles.tiles_x) * tiles.tiles_y + 1, 0);
    for (const Placed& p : sorted)
        for (int ty = p.range[2]; ty <= p.range[3]; ++ty)
            for (int tx = p.range[0]; tx <= p.range[1]; ++tx) ++counts[ty * tiles.tiles_x + tx];
    tiles.offsets.resize(counts.size());
    std::uint32_t total = 0;
    for (std::size_t t = 0; t < counts.size(); ++t) {
        tiles.offsets[t] = total;
        total += counts[t];
    }
    tiles.items.resize(total);
    tiles.nearest.resize(total);
    tiles.rows.resize(total);
    std::vector<std::uint32_t> next(tiles.offsets.begin(), tiles.offsets.end() - 1);
    for (const Placed& p : sorted)
        for (int ty = p.range[2]; ty <= p.range[3]; ++ty)
            for (int tx = p.range[0]; tx <= p.range[1]; ++tx) {
                std::uint32_t slot = next[ty * tiles.tiles_x + tx]++;
                tiles.items[slot] = p.item;
                tiles.nearest[slot] = p.nearest;
                tiles.rows[slot] = p.rows;
            }
    return tiles;
}

}  // namespace clr
