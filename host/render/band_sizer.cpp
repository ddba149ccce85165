#include "render/band_sizer.h"

#include <algorithm>
#include <cmath>

#include "shared/clr_types.h"

namespace clr {
namespace {

// The first band of a run, before anything is measured, holds this much work (samples x row
// work): a small fraction of the band target on the slowest device measured, so that a stop
// request during it waits little on any device (docs/architecture.md, "Bands of rows: a frame
// that can be stopped").
constexpr double kFirstBandWork = 1 << 18;
// A band may hold at most this many times the rows of the band before it: a second guard,
// besides row_work(), against rows much costlier than the estimate says (mirrors, shadows).
constexpr int kGrowth = 4;

}  // namespace

std::vector<double> row_work(const ScreenTiles& tiles, int width, int height) {
    // Each item adds to a run of rows: counted as a start and an end (over 300,000 items at
    // 100,000 spheres), then summed over the rows once.
    std::vector<double> change(static_cast<std::size_t>(height) + 1, 0);
    const int tile_count = static_cast<int>(tiles.offsets.size()) - 1;
    for (int tile_row_start = 0, tile_top = 0; tile_row_start < tile_count;
         tile_row_start += std::max(1, tiles.tiles_x), tile_top += kClrTileSize) {
        const int tile_bottom = std::min(tile_top + kClrTileSize, height) - 1;
        const int tile_row_end = std::min(tile_count, tile_row_start + std::max(1, tiles.tiles_x));
        for (std::uint32_t item = tiles.offsets[tile_row_start]; item < tiles.offsets[tile_row_end]; ++item) {
            int first = std::max(tile_top, static_cast<int>(tiles.rows[item] >> 16));
            int last = std::min(tile_bottom, static_cast<int>(tiles.rows[item] & 0xffff));
            if (first > last) continue;
            change[first] += kClrTileSize;
            change[last + 1] -= kClrTileSize;
        }
    }
    std::vector<double> work(height, width);
    double running = 0;
    for (int row = 0; row < height; ++row) work[row] += running += change[row];
    return work;
}

std::vector<double> row_work(int objects, int width, int height) {
    return std::vector<double>(height, static_cast<double>(width) * (1 + objects));
}

std::vector<double> row_work_through_bvh(std::size_t objects, int width, int height) {
    return row_work(static_cast<int>(std::ceil(std::log2(static_cast<double>(objects) + 1))), width, height);
}

BandSizer::BandSizer(double target_seconds) : target_seconds_(target_seconds) {}

void BandSizer::start_frame(std::vector<double> work, int samples, int width) {
    height_ = static_cast<int>(work.size());
    width_ = std::max(1, width);
    work_before_.assign(work.size() + 1, 0);
    for (std::size_t row = 0; row < work.size(); ++row) work_before_[row + 1] = work_before_[row] + work[row];
    samples_ = std::max(1, samples);
    previous_rows_ = 0;
}

double BandSizer::work_of(int first_row, int rows) const {
    return (work_before_[first_row + rows] - work_before_[first_row]) * samples_;
}

int BandSizer::rows_within(int first_row, double work) const {
    double end = work_before_[first_row] + work / samples_;
    auto last = std::upper_bound(work_before_.begin() + first_row + 1, work_before_.end(), end);
    return static_cast<int>(last - work_before_.begin()) - 1 - first_row;
}

int BandSizer::next_rows(int first_row, int limit) const {
    const int left = std::min(height_ - first_row, limit);
    int rows;
    if (seconds_per_work_ == 0)
        rows = rows_within(first_row, kFirstBandWork);
    else if (previous_rows_ == 0)
        // A later frame of the same scene: sized by the last frame's rate, with margin for
        // what the estimate of its rows misses.
        rows = rows_within(first_row, target_seconds_ / 2 / seconds_per_work_);
    else
        rows = std::min(rows_within(first_row, target_seconds_ / seconds_per_work_), kGrowth * previous_rows_);
    const double most_rows = kMostSamplesPerBand / (static_cast<double>(width_) * samples_);
    rows = static_cast<int>(std::min<double>(rows, std::max(1.0, most_rows)));
    // Bands that end on a screen tile's last row give the packet kernel whole tiles.
    if (rows >= kClrTileSize) rows = (first_row + rows) / kClrTileSize * kClrTileSize - first_row;
    // A last sliver of rows would cost a launch of its own: the band takes it along.
    if (left - rows < rows / 4) rows = left;
    return std::clamp(rows, 1, std::max(1, left));
}

void BandSizer::band_done(int first_row, int rows, double seconds) {
    previous_rows_ = rows;
    double work = work_of(first_row, rows);
    if (work > 0 && seconds > 0) seconds_per_work_ = seconds / work;
}

}  // namespace clr
