#include "render/screen_tiles.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <memory>
#include <optional>

#include "core/parallel_for.h"
#include "core/radix_sort.h"
#include "core/usable_cpus.h"
#include "kinds/kinds.h"
#include "render/object_bounds.h"
#include "render/scene_item.h"

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

// Frames with this many objects bin on every usable core: below, handing the work to other
// threads costs more than it saves (a course frame bins five objects in microseconds).
constexpr std::size_t kParallelFrom = 16384;
// Objects per task while placing; bands of tile rows per thread while listing.
constexpr std::size_t kPlaceChunk = 4096;
constexpr int kBandsPerThread = 4;

// Object `index` of the frame (kind by kind, kinds/kinds.h) as the tiles list it, or nothing
// when no tile does.
std::optional<Placed> place(const FrameGeometry& frame, std::size_t index, const ObjectBounds& bounds,
                            const ScreenTiles& tiles, const FrameCamera& camera) {
    std::uint32_t item = 0;
    double nearest = 0;
    PixelBounds pixels;
    bool found = false;
    for_each_kind([&](auto kind) {
        using Kind = decltype(kind);
        const std::size_t count = Kind::count(frame);
        if (found) return;
        if (index >= count) {
            index -= count;
            return;
        }
        found = true;
        const auto& object = Kind::object(frame, index);
        const Vec3 object_origin = Kind::origin(frame, index);
        item = scene_item(Kind::kHit, index);
        nearest = Kind::least_distance(bounds, object, object_origin);
        pixels = Kind::pixel_bounds(bounds, object, object_origin);
    });
    Placed placed;
    if (!tile_range(pixels, tiles, camera.width, camera.height, pixel_margin(camera.samples), placed.range, placed.rows))
        return std::nullopt;
    placed.item = item;
    // Stored slightly low: a float32 hit distance may fall a few ulps short of the true one,
    // and the kernel must never skip an object that its float ray does hit first.
    placed.nearest = static_cast<float>(nearest * (1 - 1e-5));
    return placed;
}

// The order in which tiles list a placed object: its bound's bits (a float >= 0 orders as its
// bits do), then its index in the frame, so that every tile's list is nearest first in a
// deterministic order.
std::uint64_t order_key(const Placed& placed, std::size_t index) {
    std::uint32_t bits;
    std::memcpy(&bits, &placed.nearest, sizeof bits);
    return static_cast<std::uint64_t>(bits) << 32 | index;
}

// The frame's objects that some tile lists, nearest first.
std::vector<Placed> nearest_first(const FrameGeometry& frame, const ScreenTiles& tiles, const FrameCamera& camera,
                                  std::size_t threads) {
    const ObjectBounds bounds(camera);
    const std::size_t objects = frame.object_count();
    // Each chunk of objects places into its own slots and keys; the sort makes one order of them.
    std::unique_ptr<Placed[]> by_index(new Placed[objects]);  // written before read: no zero fill
    std::vector<std::vector<std::uint64_t>> chunk_keys((objects + kPlaceChunk - 1) / kPlaceChunk);
    parallel_for(chunk_keys.size(), threads, [&](std::size_t chunk) {
        const std::size_t end = std::min(objects, (chunk + 1) * kPlaceChunk);
        for (std::size_t index = chunk * kPlaceChunk; index < end; ++index) {
            if (std::optional<Placed> placed = place(frame, index, bounds, tiles, camera)) {
                by_index[index] = *placed;
                chunk_keys[chunk].push_back(order_key(*placed, index));
            }
        }
    });
    std::vector<std::uint64_t> keys;
    for (const std::vector<std::uint64_t>& chunk : chunk_keys) keys.insert(keys.end(), chunk.begin(), chunk.end());
    radix_sort(keys);
    std::vector<Placed> sorted(keys.size());
    parallel_for(chunk_keys.size(), threads, [&](std::size_t chunk) {
        const std::size_t end = std::min(keys.size(), (chunk + 1) * kPlaceChunk);
        for (std::size_t k = chunk * kPlaceChunk; k < end; ++k) sorted[k] = by_index[static_cast<std::uint32_t>(keys[k])];
    });
    return sorted;
}

// Calls visit(tile) for each tile of tile rows [first_row, end_row) that lists `placed`.
template <typename Visit>
void for_each_tile_in_rows(const Placed& placed, int tiles_x, int first_row, int end_row, Visit visit) {
    const int row_begin = std::max(placed.range[2], first_row), row_end = std::min(placed.range[3] + 1, end_row);
    for (int ty = row_begin; ty < row_end; ++ty)
        for (int tx = placed.range[0]; tx <= placed.range[1]; ++tx) visit(ty * tiles_x + tx);
}

}  // namespace

ScreenTiles bin_screen_tiles(const FrameGeometry& frame, const FrameCamera& camera) {
    ScreenTiles tiles;
    tiles.tiles_x = (camera.width + kClrTileSize - 1) / kClrTileSize;
    tiles.tiles_y = (camera.height + kClrTileSize - 1) / kClrTileSize;
    const std::size_t threads = frame.object_count() >= kParallelFrom ? static_cast<std::size_t>(usable_cpu_count()) : 1;
    const std::vector<Placed> sorted = nearest_first(frame, tiles, camera, threads);
    // Two passes over flat arrays (count per tile, then fill nearest first), without a list
    // per tile: a frame bins anew, and a vector per tile (thousands at 1080p) would be
    // allocated and freed every frame (docs/benchmarks.md). Each task takes a band of tile rows
    // and writes only its tiles' counts and slots, in the one nearest-first order.
    const int bands = static_cast<int>(std::min<std::size_t>(threads * kBandsPerThread, tiles.tiles_y));
    auto band_rows = [&](std::size_t band, int& first, int& end) {
        first = static_cast<int>(band * tiles.tiles_y / bands);
        end = static_cast<int>((band + 1) * tiles.tiles_y / bands);
    };
    std::vector<std::uint32_t> counts(static_cast<std::size_t>(tiles.tiles_x) * tiles.tiles_y + 1, 0);
    parallel_for(bands, threads, [&](std::size_t band) {
        int first, end;
        band_rows(band, first, end);
        for (const Placed& p : sorted) for_each_tile_in_rows(p, tiles.tiles_x, first, end, [&](int t) { ++counts[t]; });
    });
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
    parallel_for(bands, threads, [&](std::size_t band) {
        int first, end;
        band_rows(band, first, end);
        for (const Placed& p : sorted)
            for_each_tile_in_rows(p, tiles.tiles_x, first, end, [&](int t) {
                std::uint32_t slot = next[t]++;
                tiles.items[slot] = p.item;
                tiles.nearest[slot] = p.nearest;
                tiles.rows[slot] = p.rows;
            });
    });
    return tiles;
}

}  // namespace clr
