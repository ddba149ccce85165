// The second half of binning the screen tiles (screen_tiles.h): once every object's tiles and
// bound are known, each tile's list of them, nearest first. On every frame of a moving camera,
// for every object in view (100,000 spheres in a benchmark scene), so it runs on several
// threads and passes over each object only where it covers something.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/radix_sort.h"

namespace clr {

struct ScreenTiles;  // render/screen_tiles.h

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

// list_in_tiles() with working arrays kept from call to call, and kept in `tiles` too where it
// had them: a renderer lists every frame, 12 MB of arrays for 100,000 spheres, which fresh
// from the system cost a page fault and a zero fill per 4 KB every frame.
class TileLister {
public:
    // `memory_budget`: the most bytes the lists of one frame may take (default: half of this
    // machine's memory). Objects that overlap on the screen thousands deep (a file of one
    // triangle repeated 200,000 times, each covering the screen) would ask for tens of GB, and
    // the system would kill the process; list() throws an Error with kExitOutOfMemory naming
    // the figures instead, before anything is allocated.
    explicit TileLister(std::uint64_t memory_budget = default_tile_memory_budget());
    void list(const std::vector<TileSpan>& spans, std::size_t threads, ScreenTiles& tiles);

    // Half of this machine's physical memory.
    static std::uint64_t default_tile_memory_budget();

private:
    // A span as the tiles of one tile row list it.
    struct RowEntry {
        std::uint32_t item;
        float nearest;
        std::uint32_t rows;
        int first_column, last_column;
    };
    void sort_nearest_first(const std::vector<TileSpan>& spans, std::size_t threads);
    void split_into_rows(int tiles_x, int tiles_y, std::size_t threads);

    // Throws when the lists of `entries` tile entries and `row_entries` row entries exceed the
    // budget; `tiles` is the grid's tile count, for the message.
    void check_budget(std::uint64_t entries, std::uint64_t row_entries, std::uint64_t tiles) const;

    std::uint64_t memory_budget_;
    std::vector<std::uint64_t> keys_;
    RadixSortScratch sort_scratch_;
    std::vector<TileSpan> sorted_;  // the spans nearest first
    // Per tile row, the spans that reach it, nearest first: row r's are
    // row_spans_[row_starts_[r] .. row_starts_[r + 1]), and its first tile's entries begin at
    // row_first_entry_[r] in the lists.
    std::vector<std::uint32_t> row_starts_, row_first_entry_;
    std::vector<RowEntry> row_spans_;
    std::vector<std::uint32_t> chunk_rows_;    // [chunk][row]: spans, then the next slot
    std::vector<std::uint64_t> chunk_entries_;  // [chunk][row]: tile entries
};

}  // namespace clr
