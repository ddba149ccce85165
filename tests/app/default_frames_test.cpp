// --frames on an animation without -o or --video: the selected frames are written as
// <scene>_NNNN.png beside where <scene>.png would go, and no video, so that an earlier
// <scene>.mp4 of the whole animation is never replaced by a video of a few frames.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/command.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::run_clrender;
using testing::TempFolder;

// 11 frames (two keys, the default ten frames per segment); `extra` adds members.
std::string animation(const std::string& extra = "") {
    return R"({"eyeLocations": [[-3, 1, 8], [3, 2, 7]], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 55,
      "width": 16, "height": 12, "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0.3, 0.2]}])" +
           extra + "}";
}

TEST(DefaultFrames, ASelectionWritesFramesAndLeavesTheVideoAlone) {
    TempFolder folder;
    folder.write("anim.json", animation());
    folder.write("anim.mp4", "the whole animation's video, rendered earlier");
    auto result = run_clrender("anim.json --frames 3,5", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_TRUE(fs::is_regular_file(folder.file("anim_0003.png")));
    EXPECT_TRUE(fs::is_regular_file(folder.file("anim_0005.png")));
    EXPECT_FALSE(fs::exists(folder.file("anim_0004.png"))) << "only the selected frames";
    EXPECT_EQ(read_bytes(folder.file("anim.mp4")), "the whole animation's video, rendered earlier");
    EXPECT_EQ(folder.entry_count(), 4) << "no other file, no video";
    EXPECT_NE(result.output.find("clrender: wrote anim_0003.png ... anim_0005.png (2 frames); no video"),
              std::string::npos)
        << result.output;
}

TEST(DefaultFrames, OneFrameIsNamedInTheSummary) {
    TempFolder folder;
    folder.write("anim.json", animation());
    auto result = run_clrender("anim.json --frames 10", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_TRUE(fs::is_regular_file(folder.file("anim_0010.png")));
    EXPECT_NE(result.output.find("clrender: wrote anim_0010.png; no video"), std::string::npos) << result.output;
}

TEST(DefaultFrames, AreTheFramesThatAPatternWrites) {
    TempFolder folder;
    folder.write("anim.json", animation());
    ASSERT_EQ(run_clrender("anim.json -q --frames 7", folder.path()).exit_code, 0);
    ASSERT_EQ(run_clrender("anim.json -q --frames 7 -o 'f_%04d.png'", folder.path()).exit_code, 0);
    EXPECT_EQ(read_bytes(folder.file("anim_0007.png")), read_bytes(folder.file("f_0007.png")));
}

TEST(DefaultFrames, GetMoreDigitsWhenTheAnimationHasMoreFrames) {
    TempFolder folder;
    folder.write("long.json", animation(R"(, "clrender": {"frames": 12000})"));
    auto result = run_clrender("long.json -q --frames 7,11999", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_TRUE(fs::is_regular_file(folder.file("long_00007.png")));
    EXPECT_TRUE(fs::is_regular_file(folder.file("long_11999.png")));
}

// The scene's name is text, not a pattern: a '%d' or '#' in it stays as it is.
TEST(DefaultFrames, ASceneNameWithPatternCharactersIsKept) {
    TempFolder folder;
    folder.write("a%d#.json", animation());
    auto result = run_clrender("'a%d#.json' -q --frames 2", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_TRUE(fs::is_regular_file(folder.file("a%d#_0002.png")));
}

TEST(DefaultFrames, TheWholeAnimationWithoutOptionsIsStillAVideo) {
    TempFolder folder;
    folder.write("anim.json", animation());
    // A missing encoder shows which output was planned, without rendering or encoding.
    auto result = run_clrender("anim.json -q", folder.path(), "CLRENDER_FFMPEG=/nonexistent/ffmpeg");
    EXPECT_EQ(result.exit_code, 4) << result.output;
    EXPECT_NE(result.output.find("/nonexistent/ffmpeg"), std::string::npos) << result.output;
    // With --frames, no encoder is needed at all.
    result = run_clrender("anim.json -q --frames 0-10", folder.path(), "CLRENDER_FFMPEG=/nonexistent/ffmpeg");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_TRUE(fs::is_regular_file(folder.file("anim_0010.png")));
}

TEST(DefaultFrames, ResumeSkipsTheFramesWritten) {
    TempFolder folder;
    folder.write("anim.json", animation());
    ASSERT_EQ(run_clrender("anim.json -q --frames 0-2", folder.path()).exit_code, 0);
    const std::string frame_2 = read_bytes(folder.file("anim_0002.png"));
    const auto written = fs::last_write_time(folder.file("anim_0002.png"));
    const std::string frame_0 = read_bytes(folder.file("anim_0000.png"));
    folder.write("anim_0000.png", "not a PNG: rendered again");
    fs::remove(folder.file("anim_0001.png"));
    auto result = run_clrender("anim.json -q --frames 0-2 --resume", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_EQ(read_bytes(folder.file("anim_0000.png")), frame_0);
    EXPECT_NE(result.output.find("clrender: warning: anim_0000.png: cannot be read (not a PNG file); rendering it again"),
              std::string::npos)
        << result.output;
    EXPECT_TRUE(fs::is_regular_file(folder.file("anim_0001.png")));
    EXPECT_EQ(fs::last_write_time(folder.file("anim_0002.png")), written) << "a finished frame is not written again";
    EXPECT_EQ(read_bytes(folder.file("anim_0002.png")), frame_2);
}

}  // namespace
}  // namespace clr
