#include "app/progress.h"

#include <gtest/gtest.h>

namespace clr {
namespace {

TEST(Progress, DurationsReadAsMinutesAndHours) {
    EXPECT_EQ(format_duration(0), "0:00");
    EXPECT_EQ(format_duration(59.4), "0:59");
    EXPECT_EQ(format_duration(65), "1:05");
    EXPECT_EQ(format_duration(3600), "1:00:00");
    EXPECT_EQ(format_duration(12 * 3600 + 3 * 60 + 7), "12:03:07");
    EXPECT_EQ(format_duration(-3), "0:00");
}

TEST(Progress, TheBarShowsPercentElapsedAndTimeLeft) {
    EXPECT_EQ(format_progress_bar(0.25, 0, 1, 10),
              "clrender: [#####               ]  25%  elapsed 0:10  left 0:30");
    // An animation's bar shows frames per second once a frame is done (docs/animation.md).
    EXPECT_EQ(format_progress_bar(0.25, 0, 4, 3), "clrender: [#####               ]  25%  frame 1/4  elapsed 0:03  left 0:09");
    EXPECT_EQ(format_progress_bar(0.5, 2, 4, 65),
              "clrender: [##########          ]  50%  frame 3/4  0.03 frames/s  elapsed 1:05  left 1:05");
    EXPECT_EQ(format_progress_bar(1, 4, 4, 8),
              "clrender: [####################] 100%  frame 4/4  0.50 frames/s  elapsed 0:08  left 0:00");
    EXPECT_EQ(format_progress_bar(0.5, 30, 60, 12.5),
              "clrender: [##########          ]  50%  frame 31/60  2.4 frames/s  elapsed 0:13  left 0:13");
    EXPECT_EQ(format_progress_bar(0.5, 300, 600, 12.5),
              "clrender: [##########          ]  50%  frame 301/600  24 frames/s  elapsed 0:13  left 0:13");
    EXPECT_EQ(format_progress_bar(0, 0, 1, 3), "clrender: [                    ]   0%  elapsed 0:03  left ?")
        << "nothing done yet: no estimate";
}

TEST(Progress, JsonLinesHoldTheDocumentedKeys) {
    EXPECT_EQ(format_progress_json(7, 12, 5, 5.0 / 12, 3.5),
              R"({"elapsed_s":3.5,"eta_s":4.9,"frame":7,"frames":12,"frames_done":5,"percent":41.7})");
    EXPECT_EQ(format_progress_json(0, 1, 0, 0, 0.25),
              R"({"elapsed_s":0.25,"eta_s":null,"frame":0,"frames":1,"frames_done":0,"percent":0.0})");
}

TEST(Progress, StylesByName) {
    EXPECT_EQ(progress_style_named("json"), ProgressStyle::Json);
    EXPECT_EQ(progress_style_named("none"), ProgressStyle::None);
    EXPECT_EQ(progress_style_named("bar"), ProgressStyle::Bar);
}

}  // namespace
}  // namespace clr
