// The second half of binning the screen tiles (screen_tiles.h): once every object's tiles and
// bound are known, each tile's list of them, nearest first. On every frame of a moving camera,
// for every object in view (100,000 spheres in a benchmark scene), so it runs on several
// threads and passes over each object only where it covers something.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "render/screen_tiles.h"

namespace clr {

// An object that some tiles list: what each of its entries holds, and which tiles list it.
struct TileSpan {
    std::uint32_t item = 0;  // ScreenTiles::items
    float nearest = 0;       // ScreenTiles::nearest, >= 0
    std::uint32_t rows = 0;  // ScreenTiles::rows
    // Tile columns and tile rows, inclusive, inside the tile grid.
    int first_column = 0, last_column = 0, first_row = 0, last_row = 0;
};

// Fills tiles.offsets, items, nearest and rows for the grid of tiles.tiles_x by tiles.tiles_y:
// each tile lists the spans that cover it by ascending `nearest`, equal ones in the order of
// `spans`. Uses up to `threads` threads (parallel_for); the lists are the same bytes for any
// count, so that no thread's timing can change a frame.
void list_in_tiles(const std::vector<TileSpan>& spans, std::size_t threads, ScreenTiles& tiles);

}  // namespace clr
