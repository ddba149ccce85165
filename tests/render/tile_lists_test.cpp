// list_in_tiles() lists each span in the tiles it covers, nearest first and equal bounds in
// the spans' order, and gives the same bytes on any number of threads: checked against lists
// made the plain way, a vector per tile, sorted stably.
#include "render/tile_lists.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "core/errors.h"
#include "core/worker_threads.h"
#include "render/screen_tiles.h"

namespace clr {
namespace {

// The plain way: each tile's spans in the order of `spans`, then sorted stably by bound.
ScreenTiles plain_lists(const std::vector<TileSpan>& spans, int tiles_x, int tiles_y) {
    std::vector<std::vector<TileSpan>> per_tile(static_cast<std::size_t>(tiles_x) * tiles_y);
    for (const TileSpan& span : spans)
        for (int row = span.first_row; row <= span.last_row; ++row)
            for (int column = span.first_column; column <= span.last_column; ++column)
                per_tile[row * tiles_x + column].push_back(span);
    ScreenTiles tiles;
    tiles.tiles_x = tiles_x;
    tiles.tiles_y = tiles_y;
    for (std::vector<TileSpan>& list : per_tile) {
        std::stable_sort(list.begin(), list.end(), [](const TileSpan& a, const TileSpan& b) { return a.nearest < b.nearest; });
        tiles.offsets.push_back(static_cast<std::uint32_t>(tiles.items.size()));
        for (const TileSpan& span : list) {
            tiles.items.push_back(span.item);
            tiles.nearest.push_back(span.nearest);
            tiles.rows.push_back(span.rows);
        }
    }
    tiles.offsets.push_back(static_cast<std::uint32_t>(tiles.items.size()));
    return tiles;
}

// `count` spans over a grid of tiles_x by tiles_y: mostly a tile or a few, some whole rows,
// columns or the whole grid; half the bounds from few values, so that many tie, half from all
// the float bits of a range.
std::vector<TileSpan> random_spans(std::size_t count, int tiles_x, int tiles_y, unsigned seed) {
    std::mt19937 random(seed);
    auto between = [&](int low, int high) { return std::uniform_int_distribution<int>(low, high)(random); };
    std::vector<TileSpan> spans(count);
    for (std::size_t i = 0; i < count; ++i) {
        TileSpan& span = spans[i];
        span.item = static_cast<std::uint32_t>(i * 7 + 3);
        span.nearest = i % 2 ? static_cast<float>(between(0, 40)) * 0.25f
                             : std::uniform_real_distribution<float>(0, 100)(random);
        span.rows = static_cast<std::uint32_t>(between(0, 1 << 20));
        span.first_column = between(0, tiles_x - 1);
        span.first_row = between(0, tiles_y - 1);
        const int shape = between(0, 99);
        span.last_column = std::min(tiles_x - 1, span.first_column + (shape < 90 ? between(0, 2) : tiles_x));
        span.last_row = std::min(tiles_y - 1, span.first_row + (shape < 80 ? between(0, 2) : tiles_y));
        if (shape == 99) span = {span.item, span.nearest, span.rows, 0, tiles_x - 1, 0, tiles_y - 1};
    }
    return spans;
}

void expect_same_lists(const ScreenTiles& expected, const ScreenTiles& actual) {
    EXPECT_EQ(actual.offsets, expected.offsets);
    EXPECT_EQ(actual.items, expected.items);
    EXPECT_EQ(actual.nearest, expected.nearest);
    EXPECT_EQ(actual.rows, expected.rows);
}

ScreenTiles listed(const std::vector<TileSpan>& spans, int tiles_x, int tiles_y, std::size_t threads) {
    ScreenTiles tiles;
    tiles.tiles_x = tiles_x;
    tiles.tiles_y = tiles_y;
    list_in_tiles(spans, threads, tiles);
    return tiles;
}

TEST(TileLists, ListEachTilesSpansNearestFirstTiesInTheirOrderOnAnyThreadCount) {
    WorkerThreads::shared().start(3);  // so that the loops below do run on several threads
    const int tiles_x = 40, tiles_y = 23;
    // Many chunks of spans, so that chunks placed by different threads meet in each row.
    const std::vector<TileSpan> spans = random_spans(30000, tiles_x, tiles_y, 5);
    const ScreenTiles expected = plain_lists(spans, tiles_x, tiles_y);
    ASSERT_GT(expected.items.size(), 60000u);
    for (std::size_t threads : {1u, 2u, 4u}) {
        SCOPED_TRACE(threads);
        expect_same_lists(expected, listed(spans, tiles_x, tiles_y, threads));
    }
}

TEST(TileLists, FewOrNoSpansAndGridsOfOneTile) {
    for (std::size_t count : {0u, 1u, 7u, 4096u, 4097u}) {
        for (auto [tiles_x, tiles_y] : {std::pair{1, 1}, {1, 9}, {9, 1}, {5, 4}}) {
            SCOPED_TRACE(::testing::Message() << count << " spans, " << tiles_x << "x" << tiles_y);
            const std::vector<TileSpan> spans = random_spans(count, tiles_x, tiles_y, static_cast<unsigned>(count + tiles_x));
            expect_same_lists(plain_lists(spans, tiles_x, tiles_y), listed(spans, tiles_x, tiles_y, 2));
        }
    }
}

// A renderer lists every frame with one lister, into the last frame's lists: whatever the
// frame before held (more spans or fewer, another grid), the lists are a fresh call's.
TEST(TileLists, AListerKeptFromFrameToFrameListsEachFrameAsAFreshOne) {
    WorkerThreads::shared().start(2);
    const std::vector<TileSpan> large = random_spans(30000, 40, 23, 7), small = random_spans(5000, 17, 9, 8);
    TileLister lister;
    ScreenTiles tiles;
    for (const auto* frame : {&large, &small, &small, &large}) {
        const int tiles_x = frame == &large ? 40 : 17, tiles_y = frame == &large ? 23 : 9;
        tiles.tiles_x = tiles_x;
        tiles.tiles_y = tiles_y;
        lister.list(*frame, 2, tiles);
        expect_same_lists(plain_lists(*frame, tiles_x, tiles_y), tiles);
    }
}

// Objects that overlap on the screen far beyond what memory holds are refused before their
// lists are made, naming the figures: 50 spans over the whole 10x10 grid are 5,000 entries of
// 12 bytes and 500 row entries of 20, 70,000 bytes, listed within a budget of exactly that.
TEST(TileLists, ListsBeyondTheMemoryBudgetAreRefusedBeforeTheyAreMade) {
    std::vector<TileSpan> spans(50);
    for (std::size_t i = 0; i < spans.size(); ++i)
        spans[i] = {static_cast<std::uint32_t>(i), 1.0f + static_cast<float>(i), 0u, 0, 9, 0, 9};
    ScreenTiles tiles;
    tiles.tiles_x = tiles.tiles_y = 10;
    try {
        TileLister(69999).list(spans, 1, tiles);
        FAIL() << "listed beyond the budget";
    } catch (const Error& error) {
        EXPECT_EQ(error.code(), kExitOutOfMemory);
        EXPECT_NE(std::string(error.what()).find("would list 5000 objects"), std::string::npos) << error.what();
        EXPECT_NE(std::string(error.what()).find("overlap on the screen 50 deep"), std::string::npos) << error.what();
    }
    TileLister(70000).list(spans, 1, tiles);
    expect_same_lists(plain_lists(spans, 10, 10), tiles);
}

}  // namespace
}  // namespace clr
