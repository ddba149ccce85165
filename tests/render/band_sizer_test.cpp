// The band sizer starts a run with a short band, then sizes bands to the target time from what
// earlier bands took per unit of estimated row work, so that cheap rows (sky) do not make the
// band over expensive ones far too long.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>

#include "render/band_sizer.h"

namespace clr {
namespace {

constexpr double kTarget = 0.15;

struct Band {
    int first, rows;
    double seconds;
};

// Splits a frame the way Renderer::render_bands does, row `row` taking `row_seconds(row)`.
std::vector<Band> split_frame(BandSizer& sizer, const std::vector<double>& work, int samples, int width,
                              const std::function<double(int)>& row_seconds) {
    sizer.start_frame(work, samples, width);
    const int height = static_cast<int>(work.size());
    std::vector<Band> bands;
    for (int first = 0; first < height;) {
        int rows = sizer.next_rows(first, height);
        EXPECT_GE(rows, 1);
        EXPECT_LE(first + rows, height);
        double seconds = 0;
        for (int row = first; row < first + rows; ++row) seconds += row_seconds(row);
        sizer.band_done(first, rows, seconds);
        bands.push_back({first, rows, seconds});
        first += rows;
    }
    return bands;
}

TEST(BandSizer, BandsOfALongFrameTakeAboutTheTargetTime) {
    BandSizer sizer(kTarget);
    // 4096 rows of 10 ms each: 41 s in all.
    std::vector<double> work = row_work(10, 4096, 4096);
    std::vector<Band> bands = split_frame(sizer, work, 64, 4096, [](int) { return 0.01; });
    EXPECT_LE(bands.front().seconds, 0.05) << "the first band, before any measurement, is short";
    for (const Band& band : bands) EXPECT_LE(band.seconds, kTarget * 1.3) << band.first;
    long near_target = std::count_if(bands.begin(), bands.end(), [](const Band& band) { return band.seconds >= kTarget * 0.5; });
    EXPECT_GE(near_target, static_cast<long>(bands.size()) - 4) << "after a short ramp, bands are not needlessly small";

    // The next frame starts from what this one measured.
    std::vector<Band> next = split_frame(sizer, work, 64, 4096, [](int) { return 0.01; });
    EXPECT_GE(next.front().seconds, kTarget * 0.3);
    EXPECT_LE(next.front().seconds, kTarget * 1.3);
}

TEST(BandSizer, RowsThatCostMoreWorkGetSmallerBands) {
    BandSizer sizer(kTarget);
    // Sky above a dense scene whose rows the estimate says cost 40 times more, and do.
    std::vector<double> work(2048, 2048);
    for (int row = 1024; row < 2048; ++row) work[row] *= 40;
    std::vector<Band> bands = split_frame(sizer, work, 16, 2048, [](int row) { return row < 1024 ? 0.0005 : 0.02; });
    for (const Band& band : bands) EXPECT_LE(band.seconds, kTarget * 1.3) << band.first << " +" << band.rows;
}

TEST(BandSizer, RowsCostlierThanTheEstimateSaysStillGiveShortBands) {
    BandSizer sizer(kTarget);
    // A 4096x4096 still at 128 samples: empty sky whose tiles the packet kernel skips (a
    // microsecond a row), then a mirrored floor whose rows the estimate calls equal to the
    // sky's but that cost 10 ms each. Bands grown over the sky (fourfold each time) would take
    // many seconds over the floor: the demo scene at this size once took 14 s to stop.
    std::vector<double> work = row_work(1, 4096, 4096);
    std::vector<Band> bands = split_frame(sizer, work, 128, 4096, [](int row) { return row < 2048 ? 1e-6 : 0.01; });
    for (const Band& band : bands) EXPECT_LE(band.seconds, 1.0) << band.first << " +" << band.rows;
    for (const Band& band : bands)
        EXPECT_LE(double(band.rows) * 4096 * 128, BandSizer::kMostSamplesPerBand) << band.first << " +" << band.rows;
}

TEST(BandSizer, AQuickFrameIsOneBand) {
    BandSizer sizer(kTarget);
    std::vector<double> work = row_work(5, 640, 360);
    split_frame(sizer, work, 1, 640, [](int) { return 1e-5; });  // measured once
    EXPECT_EQ(split_frame(sizer, work, 1, 640, [](int) { return 1e-5; }).size(), 1u);
}

TEST(BandSizer, BandsEndOnScreenTileRows) {
    BandSizer sizer(kTarget);
    std::vector<Band> bands = split_frame(sizer, row_work(3, 1920, 1080), 4, 1920, [](int) { return 0.004; });
    ASSERT_GT(bands.size(), 3u);
    for (std::size_t i = 0; i + 1 < bands.size(); ++i) {
        if (bands[i].rows >= 16) {
            EXPECT_EQ((bands[i].first + bands[i].rows) % 16, 0) << "band " << i;
        }
    }
}

TEST(BandSizer, RowWorkCountsEachTileObjectOverTheRowsItMayCover) {
    ScreenTiles tiles;
    tiles.tiles_x = 2;
    tiles.tiles_y = 2;
    tiles.offsets = {0, 1, 1, 1, 3};  // tile 0: one object; tile 3: two
    tiles.rows = {2u << 16 | 5u, 16u << 16 | 31u, 20u << 16 | 20u};
    std::vector<double> work = row_work(tiles, 20, 24);  // the image ends at row 23
    ASSERT_EQ(work.size(), 24u);
    for (int row = 0; row < 24; ++row) {
        double expected = 20;
        if (row >= 2 && row <= 5) expected += 16;
        if (row >= 16) expected += 16;
        if (row == 20) expected += 16;
        EXPECT_EQ(work[row], expected) << row;
    }
}

}  // namespace
}  // namespace clr
