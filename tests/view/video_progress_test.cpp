// The lines of a video's render as the viewer's watcher reads them (view/video_job.h). The
// watcher is a thread of its own: a line it threw at ended the viewer (std::terminate), so a
// line of any shape must be read, as progress or as a message.
#include <gtest/gtest.h>

#include <string>

#include "view/video_job.h"

namespace clr {
namespace {

TEST(ViewVideoProgress, AProgressLineGivesItsCounts) {
    const VideoProgressLine read = read_video_progress_line(R"({"frames_done": 3, "frames": 40, "frame": 4})");
    EXPECT_EQ(read.done, 3);
    EXPECT_EQ(read.total, 40);
    EXPECT_EQ(read.frame, 5);
    EXPECT_EQ(read.message, "");
}

TEST(ViewVideoProgress, AMessageLineGivesItsMessage) {
    const VideoProgressLine error = read_video_progress_line(R"({"level": "error", "message": "out of memory"})");
    EXPECT_FALSE(error.done);
    EXPECT_EQ(error.message, "out of memory");
    EXPECT_FALSE(error.warning);
    EXPECT_TRUE(read_video_progress_line(R"({"level": "warning", "message": "a.png changed"})").warning);
    EXPECT_EQ(read_video_progress_line("Segmentation fault").message, "Segmentation fault");
    EXPECT_EQ(read_video_progress_line("").message, "");
}

// Counts that are not whole numbers from 0 (text, fractions, negative, beyond an int, arrays,
// null), or a message that is not text, make the line a message, as any other line; the frame
// is left out where it is not one.
TEST(ViewVideoProgress, AMalformedProgressLineIsAMessageNotACrash) {
    for (const std::string line : {
             R"({"frames_done": "3", "frames": 40})",
             R"({"frames_done": 3, "frames": "forty"})",
             R"({"frames_done": 1.5, "frames": 40})",
             R"({"frames_done": -1, "frames": 40})",
             R"({"frames_done": 3, "frames": 1e300})",
             R"({"frames_done": 3, "frames": 99999999999999999999})",
             R"({"frames_done": 3, "frames": 4294967296})",
             R"({"frames_done": [3], "frames": {"n": 40}})",
             R"({"frames_done": null, "frames": null})",
             R"({"frames_done": 3, "message": 7})",
             R"({"level": "error", "message": ["x"]})",
         }) {
        VideoProgressLine read;
        EXPECT_NO_THROW(read = read_video_progress_line(line)) << line;
        EXPECT_FALSE(read.done) << line;
        EXPECT_FALSE(read.total) << line;
        EXPECT_EQ(read.message, line) << line;
    }
    for (const std::string line : {R"({"frames_done": 3, "frames": 40, "frame": "x"})",
                                   R"({"frames_done": 3, "frames": 40, "frame": 2147483647})",
                                   R"({"frames_done": 3, "frames": 40, "frame": -5})"}) {
        VideoProgressLine read;
        EXPECT_NO_THROW(read = read_video_progress_line(line)) << line;
        EXPECT_EQ(read.done, 3) << line;
        EXPECT_FALSE(read.frame) << line;
    }
    EXPECT_NO_THROW(read_video_progress_line(R"({"message": "x", "level": ["warning"]})"));
}

}  // namespace
}  // namespace clr
