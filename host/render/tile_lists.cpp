#include "render/tile_lists.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <new>
#include <string>
#include <utility>

#include "core/errors.h"
#include "core/memory_budget.h"
#include "core/parallel_for.h"
#include "render/screen_tiles.h"

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

}  // namespace

TileLister::TileLister(std::uint64_t memory_budget) : memory_budget_(memory_budget) {}

std::uint64_t TileLister::default_tile_memory_budget() { return default_memory_budget(); }

void TileLister::check_budget(std::uint64_t entries, std::uint64_t row_entries, std::uint64_t tiles) const {
    constexpr std::uint64_t kEntryBytes = sizeof(std::uint32_t) + sizeof(float) + sizeof(std::uint32_t);
    const std::uint64_t bytes = entries * kEntryBytes + row_entries * sizeof(RowEntry);
    if (bytes <= memory_budget_) return;
    throw Error("out of memory: the screen tiles of this frame would list " + std::to_string(entries) +
                    " objects (" + gib_text(bytes) + ", more than the " + gib_text(memory_budget_) +
                    " they may take: half of this machine's memory): its objects overlap on the screen " +
                    std::to_string(entries / std::max<std::uint64_t>(1, tiles)) +
                    " deep on average (docs/robustness.md, Memory)",
                kExitOutOfMemory);
}

void list_in_tiles(const std::vector<TileSpan>& spans, std::size_t threads, ScreenTiles& tiles) {
    TileLister().list(spans, threads, tiles);
}

// The spans in the order every tile lists them: by their bound (a float >= 0 orders as its
// bits do), then by their place in `spans`. The place is already in order, so the sort only
// passes over the bound's bits.
void TileLister::sort_nearest_first(const std::vector<TileSpan>& spans, std::size_t threads) {
    keys_.resize(spans.size());
    const std::size_t chunks = chunk_count(spans.size());
    parallel_for(chunks, threads, [&](std::size_t chunk) {
        for_each_in_chunk(chunk, spans.size(), [&](std::size_t k) {
            std::uint32_t bits;
            std::memcpy(&bits, &spans[k].nearest, sizeof bits);
            keys_[k] = static_cast<std::uint64_t>(bits) << 32 | k;
        });
    });
    radix_sort(keys_, 32, sort_scratch_);
    sorted_.resize(spans.size());
    // Reading the spans in that order misses the cache on nearly every one (100,000 spans are
    // 2.8 MB): the loads of a few spans ahead are started early.
    constexpr std::size_t kAhead = 16;
    parallel_for(chunks, threads, [&](std::size_t chunk) {
        for_each_in_chunk(chunk, spans.size(), [&](std::size_t k) {
            if (k + kAhead < keys_.size()) __builtin_prefetch(&spans[static_cast<std::uint32_t>(keys_[k + kAhead])]);
            sorted_[k] = spans[static_cast<std::uint32_t>(keys_[k])];
        });
    });
}

// For each tile row, the spans that reach it, in order: each row then bins its own spans from
// a list that stays in the cache (a sphere a few pixels across reaches one or two of the 68
// tile rows of a 1080p frame), instead of passing over every span. A counting sort by row,
// chunk by chunk: each chunk counts its spans per row, and then writes them where the chunks
// before it in that row end, so that every row keeps the spans' order whichever thread writes
// which chunk.
void TileLister::split_into_rows(int tiles_x, int tiles_y, std::size_t threads) {
    const std::size_t chunks = chunk_count(sorted_.size());
    chunk_rows_.assign(chunks * tiles_y, 0);
    chunk_entries_.assign(chunks * tiles_y, 0);
    parallel_for(chunks, threads, [&](std::size_t chunk) {
        std::uint32_t* counts = &chunk_rows_[chunk * tiles_y];
        std::uint64_t* entries = &chunk_entries_[chunk * tiles_y];
        for_each_in_chunk(chunk, sorted_.size(), [&](std::size_t k) {
            const TileSpan& span = sorted_[k];
            for (int row = span.first_row; row <= span.last_row; ++row) {
                ++counts[row];
                entries[row] += static_cast<std::uint64_t>(span.last_column - span.first_column + 1);
            }
        });
    });
    std::uint64_t all_rows = 0, all_entries = 0;
    for (std::size_t k = 0; k < chunk_rows_.size(); ++k) {
        all_rows += chunk_rows_[k];
        all_entries += chunk_entries_[k];
    }
    check_budget(all_entries, all_rows, tiles_x * static_cast<std::uint64_t>(tiles_y));
    row_starts_.resize(static_cast<std::size_t>(tiles_y) + 1);
    row_first_entry_.resize(static_cast<std::size_t>(tiles_y) + 1);
    std::uint64_t total = 0, total_entries = 0;
    for (int row = 0; row < tiles_y; ++row) {
        row_starts_[row] = entry_count(total);
        row_first_entry_[row] = entry_count(total_entries);
        for (std::size_t chunk = 0; chunk < chunks; ++chunk) {
            std::uint32_t& slot = chunk_rows_[chunk * tiles_y + row];
            const std::uint32_t count = slot;
            slot = entry_count(total);
            total += count;
            total_entries += chunk_entries_[chunk * tiles_y + row];
        }
    }
    row_starts_[tiles_y] = entry_count(total);
    row_first_entry_[tiles_y] = entry_count(total_entries);
    row_spans_.resize(total);  // every entry written below
    parallel_for(chunks, threads, [&](std::size_t chunk) {
        std::uint32_t* next = &chunk_rows_[chunk * tiles_y];
        for_each_in_chunk(chunk, sorted_.size(), [&](std::size_t k) {
            const TileSpan& span = sorted_[k];
            const RowEntry entry{span.item, span.nearest, span.rows, span.first_column, span.last_column};
            for (int row = span.first_row; row <= span.last_row; ++row) row_spans_[next[row]++] = entry;
        });
    });
}

void TileLister::list(const std::vector<TileSpan>& spans, std::size_t threads, ScreenTiles& tiles) {
    sort_nearest_first(spans, threads);
    split_into_rows(tiles.tiles_x, tiles.tiles_y, threads);
    // Each task takes a tile row and writes only its tiles' offsets and entries, which follow
    // the rows before it: it counts its spans per tile, then lists them nearest first. Flat
    // arrays, without a list per tile: a vector per tile (thousands at 1080p) would be
    // allocated and freed every frame (docs/benchmarks.md).
    const std::size_t tiles_x = static_cast<std::size_t>(tiles.tiles_x);
    const std::size_t total = row_first_entry_[tiles.tiles_y];
    tiles.offsets.resize(tiles_x * tiles.tiles_y + 1);
    tiles.offsets.back() = static_cast<std::uint32_t>(total);
    tiles.items.resize(total);  // every entry written below
    tiles.nearest.resize(total);
    tiles.rows.resize(total);
    parallel_for(tiles.tiles_y, threads, [&](std::size_t row) {
        const RowEntry* first = row_spans_.data() + row_starts_[row];
        const RowEntry* end = row_spans_.data() + row_starts_[row + 1];
        std::uint32_t* offsets = &tiles.offsets[row * tiles_x];
        std::vector<std::uint32_t> next(tiles_x, 0);
        for (const RowEntry* span = first; span != end; ++span)
            for (int column = span->first_column; column <= span->last_column; ++column) ++next[column];
        std::uint32_t offset = row_first_entry_[row];
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
