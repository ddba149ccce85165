// How many rows the next band of a frame renders. Every frame renders in bands so that the
// stop check between them (Ctrl-C, SIGTERM) runs several times a second even while one large
// still renders; each band costs a kernel launch and a wait, so bands should not be shorter
// than that needs. The sizer measures how long bands take and aims each at a target time.
//
// Rows do not cost the same: sky is cheap, rows through many objects are not. Each row comes
// with an estimate of its work (row_work()), and the sizer measures seconds per unit of work,
// so that a band over cheap rows does not make the next one, over expensive rows, far too long.
// The estimate cannot see everything (mirrors, shadows, texture lookups), so no band holds more
// than kMostSamplesPerBand samples either: after a run of cheap rows (sky) the next band over
// costly ones (a mirrored floor) could otherwise take many seconds.
#pragma once

#include <vector>

#include "render/screen_tiles.h"

namespace clr {

// Per row of a frame: the ray-object tests of its primary rays for one sample, the pixel
// itself counting as one (so an empty row still costs its width). From the screen tiles:
// each tile's objects over the rows they may cover.
std::vector<double> row_work(const ScreenTiles& tiles, int width, int height);
// Without screen tiles every pixel tests every object.
std::vector<double> row_work(int objects, int width, int height);
// Packets that walk a BVH of `objects` (ClrSceneInfo::primary_bvh): every row alike, a walk
// growing with the tree's depth.
std::vector<double> row_work_through_bvh(std::size_t objects, int width, int height);

class BandSizer {
public:
    // `target_seconds`: the wall time a band aims at.
    explicit BandSizer(double target_seconds);

    // Samples a band holds at the most, whatever the estimate says: empty sky measures as free,
    // and bands grown over it would take seconds once they reach costly rows. This many stay
    // near the band target on the slowest device measured, so even rows ten times costlier than
    // average end a band soon (docs/architecture.md, "Bands of rows: a frame that can be stopped").
    static constexpr double kMostSamplesPerBand = 1 << 23;

    // Starts a frame of `width` pixels a row: `work` per row (row_work()), `samples` per pixel.
    void start_frame(std::vector<double> work, int samples, int width);

    // Rows for the band starting at `first_row`, at most `limit` (what one buffer holds).
    int next_rows(int first_row, int limit) const;

    // Records that the band of `rows` rows from `first_row` just took `seconds`.
    void band_done(int first_row, int rows, double seconds);

private:
    double work_of(int first_row, int rows) const;
    // The most rows from `first_row` whose work stays within `work`.
    int rows_within(int first_row, double work) const;

    double target_seconds_;
    double seconds_per_work_ = 0;  // one unit of row work, one sample; 0 until measured
    std::vector<double> work_before_;  // work of rows 0 .. r - 1, for r = 0 .. height
    int samples_ = 1;
    int width_ = 1;
    int height_ = 0;
    int previous_rows_ = 0;  // the last band of this frame; 0 before its first
};

}  // namespace clr
