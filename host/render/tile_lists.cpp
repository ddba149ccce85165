#include "render/tile_lists.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <new>
#include <utility>

#include "core/parallel_for.h"
#include "core/radix_sort.h"

namespace clr {
namespace {

// Spans per task in the passes over all spans.
constexpr std::size_t kChunk = 4096;

std::size_t chunk_count(std::size_t spans) { return (spans + kChunk - 1) / kChunk; }

// Calls visit(k) for each position k of chunk `chunk` of `count`.
template <typename Visit>
void for_each_in_chunk(std::size_t chunk, std::size_t count, Visit visit) {
    const std::size_t end = std::min(count, (chunk + 1) * kChunk);
    for (std::size_t k = chunk * kChunk; k < end; ++k) visit(k);
}

// A count of list entries as the 32-bit offsets the kernels read; more would not fit any
// device's memory (16 GiB of items alone), and is refused as such.
std::uint32_t entry_count(std::uint64_t count) {
    if (count > std::numeric_limits<std::uint32_t>::max()) throw std::bad_alloc();
    return static_cast<std::uint32_t>(count);
}

// The spans in the order every tile lists them: by their bound (a float >= 0 orders as its
// bits do), then by their place in `spans`. The place is already in order, so the sort only
// passes over the bound's bits.
std::vector<TileSpan> nearest_first(const std::vector<TileSpan>& spans, std::size_t threads) {
    std::vector<std::uint64_t> keys(spans.size());
    const std::size_t chunks = chunk_count(spans.size());
    parallel_for(chunks, threads, [&](std::size_t chunk) {
        for_each_in_chunk(chunk, spans.size(), [&](std::size_t k) {
            std::uint32_t bits;
            std::memcpy(&bits, &spans[k].nearest, sizeof bits);
            keys[k] = static_cast<std::uint64_t>(bits) << 32 | k;
        });
    });
    radix_sort(keys, 32);
    std::vector<TileSpan> sorted(spans.size());
    // Reading the spans in that order misses the cache on nearly every one (100,000 spans are
    // 2.8 MB): the loads of a few spans ahead are started early.
    constexpr std::size_t kAhead = 16;
    parallel_for(chunks, threads, [&](std::size_t chunk) {
        for_each_in_chunk(chunk, spans.size(), [&](std::size_t k) {
            if (k + kAhead < keys.size()) __builtin_prefetch(&spans[static_cast<std::uint32_t>(keys[k + kAhead])]);
            sorted[k] = spans[static_cast<std::uint32_t>(keys[k])];
        });
    });
    return sorted;
}

// A span as the tiles of one tile row list it.
struct RowEntry {
    std::uint32_t item;
    float nearest;
    std::uint32_t rows;
    int first_column, last_column;
};

// The spans that reach each tile row, nearest first, and where each row's entries begin in
// the tile lists: each row then bins its own spans, from a list that stays in the cache
// (a sphere a few pixels across reaches one or two of the 68 tile rows of a 1080p frame).
struct RowLists {
    std::vector<std::uint32_t> starts;        // row r's spans are spans[starts[r] .. starts[r + 1])
    std::vector<RowEntry> spans;
    std::vector<std::uint32_t> first_entry;   // per row: its first tile's offset in the lists
};

RowLists row_lists(const std::vector<TileSpan>& sorted, int tiles_y, std::size_t threads) {
    // A counting sort by row, chunk by chunk: each chunk counts its spans per row, and then
    // writes them where the chunks before it in that row end, so that every row keeps the
    // spans' order whichever thread writes which chunk.
    const std::size_t chunks = chunk_count(sorted.size());
    std::vector<std::uint32_t> at(chunks * tiles_y, 0);       // [chunk][row]: its count, then its next slot
    std::vector<std::uint64_t> entries(chunks * tiles_y, 0);  // [chunk][row]: its tile entries
    parallel_for(chunks, threads, [&](std::size_t chunk) {
        std::uint32_t* counts = &at[chunk * tiles_y];
        std::uint64_t* widths = &entries[chunk * tiles_y];
        for_each_in_chunk(chunk, sorted.size(), [&](std::size_t k) {
            const TileSpan& span = sorted[k];
            for (int row = span.first_row; row <= span.last_row; ++row) {
                ++counts[row];
                widths[row] += static_cast<std::uint64_t>(span.last_column - span.first_column + 1);
            }
        });
    });
    RowLists lists;
    lists.starts.resize(static_cast<std::size_t>(tiles_y) + 1);
    lists.first_entry.resize(static_cast<std::size_t>(tiles_y) + 1);
    std::uint64_t total = 0, total_entries = 0;
    for (int row = 0; row < tiles_y; ++row) {
        lists.starts[row] = entry_count(total);
        lists.first_entry[row] = entry_count(total_entries);
        for (std::size_t chunk = 0; chunk < chunks; ++chunk) {
            std::uint32_t& slot = at[chunk * tiles_y + row];
            const std::uint32_t count = slot;
            slot = entry_count(total);
            total += count;
            total_entries += entries[chunk * tiles_y + row];
        }
    }
    lists.starts[tiles_y] = entry_count(total);
    lists.first_entry[tiles_y] = entry_count(total_entries);
    lists.spans.resize(total);
    parallel_for(chunks, threads, [&](std::size_t chunk) {
        std::uint32_t* next = &at[chunk * tiles_y];
        for_each_in_chunk(chunk, sorted.size(), [&](std::size_t k) {
            const TileSpan& span = sorted[k];
            const RowEntry entry{span.item, span.nearest, span.rows, span.first_column, span.last_column};
            for (int row = span.first_row; row <= span.last_row; ++row) lists.spans[next[row]++] = entry;
        });
    });
    return lists;
}

}  // namespace

void list_in_tiles(const std::vector<TileSpan>& spans, std::size_t threads, ScreenTiles& tiles) {
    const RowLists rows = row_lists(nearest_first(spans, threads), tiles.tiles_y, threads);
    // Each task takes a tile row and writes only its tiles' offsets and entries, which follow
    // the rows before it: it counts its spans per tile, then lists them nearest first. Flat
    // arrays, without a list per tile: a frame bins anew, and a vector per tile (thousands at
    // 1080p) would be allocated and freed every frame (docs/benchmarks.md).
    const std::size_t tiles_x = static_cast<std::size_t>(tiles.tiles_x);
    const std::size_t total = rows.first_entry[tiles.tiles_y];
    tiles.offsets.resize(tiles_x * tiles.tiles_y + 1);
    tiles.offsets.back() = static_cast<std::uint32_t>(total);
    tiles.items.resize(total);
    tiles.nearest.resize(total);
    tiles.rows.resize(total);
    parallel_for(tiles.tiles_y, threads, [&](std::size_t row) {
        const RowEntry* first = rows.spans.data() + rows.starts[row];
        const RowEntry* end = rows.spans.data() + rows.starts[row + 1];
        std::uint32_t* offsets = &tiles.offsets[row * tiles_x];
        std::vector<std::uint32_t> next(tiles_x, 0);
        for (const RowEntry* span = first; span != end; ++span)
            for (int column = span->first_column; column <= span->last_column; ++column) ++next[column];
        std::uint32_t offset = rows.first_entry[row];
        for (std::size_t column = 0; column < tiles_x; ++column) {
            offsets[column] = offset;
            offset += std::exchange(next[column], offset);
        }
        for (const RowEntry* span = first; span != end; ++span)
            for (int column = span->first_column; column <= span->last_column; ++column) {
                const std::uint32_t slot = next[column]++;
                tiles.items[slot] = span->item;
                tiles.nearest[slot] = span->nearest;
                tiles.rows[slot] = span->rows;
            }
    });
}

}  // namespace clr
