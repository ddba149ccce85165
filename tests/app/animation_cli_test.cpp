// Animations from the command line: frame files, videos through ffmpeg, frame selection,
// split renders that equal one full run, the GNU parallel recipe, and encoder failures.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "support/command.h"
#include "support/small_disk.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::frame_name;
using testing::run_clrender;
using testing::TempFolder;

// Two camera keys: 11 frames by default, as the course's animations had.
const char* kAnimatedScene = R"({
  "eyeLocations": [[-3, 1, 8], [3, 2, 7]], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 55,
  "width": 64, "height": 48, "DefaultColor": [0.1, 0.1, 0.2], "SunLocation": [10, 20, 10],
  "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0.3, 0.2]},
              {"center": [2, 0.5, -2], "radius": 1, "ambient": [0, 0, 0], "IsMirror": 1}],
  "billboards": [{"UpperLeft": [-5, 4, -4], "LowerLeft": [-5, -3, -4], "UpperRight": [5, 4, -4], "ambient": [0.2, 0.6, 0.3]}]
})";

using testing::have_program;

// "codec_name=h264\nwidth=64\n..." from ffprobe, or empty without ffprobe.
std::string probe(const std::string& video) {
    TempFolder scratch;
    std::string command = "ffprobe -v error -select_streams v:0 -count_frames -show_entries "
                          "stream=codec_name,pix_fmt,width,height,nb_read_frames -of default=nw=1 '" + video + "' > '" +
                          scratch.file("probe.txt") + "' 2>&1";
    if (std::system(command.c_str()) != 0) return "";
    return read_bytes(scratch.file("probe.txt"));
}

class AnimationCli : public ::testing::Test {
protected:
    void SetUp() override { folder.write("anim.json", kAnimatedScene); }
    TempFolder folder;
};

TEST_F(AnimationCli, FrameCountFollowsTheCourseDefault) {
    auto result = run_clrender("anim.json --frame-count", folder.path());
    EXPECT_EQ(result.exit_code, 0);
    EXPECT_EQ(result.output, "11\n");
}

// Counting frames reads neither the images nor the size: a farm script asks for the count
// where the textures are not (yet) and the size comes later from --size.
TEST_F(AnimationCli, FrameCountNeedsNeitherTheImagesNorTheSize) {
    folder.write("bare.json", R"({
      "eyeLocations": [[-3, 1, 8], [3, 2, 7], [3, 2, 5]], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 55,
      "clrender": {"frames_per_segment": 4},
      "billboards": [{"UpperLeft": [-5, 4, -4], "LowerLeft": [-5, -3, -4], "UpperRight": [5, 4, -4],
                      "filename": "not-here.png"}]})");
    auto result = run_clrender("bare.json --frame-count --strict", folder.path());
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_EQ(result.output, "9\n");
    // The render itself still needs both.
    EXPECT_EQ(run_clrender("bare.json --check", folder.path()).exit_code, 2);
}

// An fps the video's format cannot hold is the scene's error, before anything renders,
// never an encoder failure after the render (or a GIF silently retimed).
TEST_F(AnimationCli, AnFpsTheVideoFormatCannotHoldIsASceneErrorAtItsKey) {
    if (!have_program("ffmpeg")) GTEST_SKIP() << "ffmpeg is not installed";
    auto gif = run_clrender("anim.json -q --reference --video fast.gif -D clrender.fps=60", folder.path());
    EXPECT_EQ(gif.exit_code, 2) << gif.output;
    EXPECT_NE(gif.output.find("clrender: error: anim.json: /clrender/fps: fps: --video fast.gif: a GIF takes from 0.001526 "
                              "to 50 frames per second"),
              std::string::npos)
        << gif.output;
    auto mp4 = run_clrender("anim.json -q --reference -D clrender.fps=0.000001", folder.path());
    EXPECT_EQ(mp4.exit_code, 2) << mp4.output;
    EXPECT_NE(mp4.output.find("/clrender/fps: fps: --video anim.mp4: an MP4 takes from 0.001 to 1000"), std::string::npos)
        << mp4.output;
    EXPECT_EQ(folder.entry_count(), 1) << "nothing written";
    // The same rate is fine for frames alone, and for the format that holds it.
    EXPECT_EQ(run_clrender("anim.json -q --reference --video ok.mp4 -D clrender.fps=60", folder.path()).exit_code, 0);
}

TEST_F(AnimationCli, DefaultOutputIsAnH264Mp4WithEveryFrame) {
    if (!have_program("ffmpeg") || !have_program("ffprobe")) GTEST_SKIP() << "ffmpeg is not installed";
    auto result = run_clrender("anim.json -q", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    std::string info = probe(folder.file("anim.mp4"));
    EXPECT_NE(info.find("codec_name=h264"), std::string::npos) << info;
    EXPECT_NE(info.find("pix_fmt=yuv420p"), std::string::npos) << info;
    EXPECT_NE(info.find("width=64"), std::string::npos) << info;
    EXPECT_NE(info.find("height=48"), std::string::npos) << info;
    EXPECT_NE(info.find("nb_read_frames=11"), std::string::npos) << info;
    EXPECT_FALSE(fs::exists(folder.file("anim.png"))) << "an animation writes frames only when -o asks";
}

TEST_F(AnimationCli, GifWithEveryFrame) {
    if (!have_program("ffmpeg") || !have_program("ffprobe")) GTEST_SKIP() << "ffmpeg is not installed";
    ASSERT_EQ(run_clrender("anim.json -q --video anim.gif", folder.path()).exit_code, 0);
    std::string info = probe(folder.file("anim.gif"));
    EXPECT_NE(info.find("codec_name=gif"), std::string::npos) << info;
    EXPECT_NE(info.find("nb_read_frames=11"), std::string::npos) << info;
}

TEST_F(AnimationCli, FramePatternWritesEveryFrameAndTheCameraMoves) {
    auto result = run_clrender("anim.json -q -o 'f_%04d.png'", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_FALSE(fs::exists(folder.file("anim.mp4"))) << "-o alone writes no video";
    for (int frame = 0; frame < 11; ++frame) ASSERT_TRUE(fs::exists(folder.file(frame_name(frame)))) << frame;
    for (int frame = 0; frame + 1 < 11; ++frame)
        EXPECT_NE(read_bytes(folder.file(frame_name(frame))), read_bytes(folder.file(frame_name(frame + 1))))
            << "frames " << frame << " and " << frame + 1 << " are the same";
    EXPECT_FALSE(fs::exists(folder.file(frame_name(11))));
}

TEST_F(AnimationCli, HashPatternAndASingleSelectedFrame) {
    ASSERT_EQ(run_clrender("anim.json -q --frames 7 -o 'g_###.ppm'", folder.path()).exit_code, 0);
    EXPECT_TRUE(fs::exists(folder.file("g_007.ppm")));
    EXPECT_FALSE(fs::exists(folder.file("g_000.ppm"))) << "only the selected frame";
    ASSERT_EQ(run_clrender("anim.json -q --frames 3 -o single.png", folder.path()).exit_code, 0);
    EXPECT_TRUE(fs::exists(folder.file("single.png")));
}

// A render farm splits the frames across processes: the frames must equal one full run's,
// byte for byte.
TEST_F(AnimationCli, FramesRenderedInSeparateProcessesEqualAFullRun) {
    fs::create_directories(folder.file("full"));
    fs::create_directories(folder.file("split"));
    ASSERT_EQ(run_clrender("anim.json -q -o 'full/f_%04d.png'", folder.path()).exit_code, 0);
    ASSERT_EQ(run_clrender("anim.json -q --frames 0-3,9 -o 'split/f_%04d.png'", folder.path()).exit_code, 0);
    ASSERT_EQ(run_clrender("anim.json -q --frames 4-8,10 -o 'split/f_%04d.png'", folder.path()).exit_code, 0);
    for (int frame = 0; frame < 11; ++frame)
        EXPECT_EQ(read_bytes(folder.file("full/" + frame_name(frame))), read_bytes(folder.file("split/" + frame_name(frame))))
            << "frame " << frame;
}

// The documented GNU parallel recipe (docs/animation.md), end to end.
TEST_F(AnimationCli, GnuParallelRecipeMatchesAFullRun) {
    if (!have_program("parallel") || !have_program("ffmpeg")) GTEST_SKIP() << "GNU parallel or ffmpeg is not installed";
    fs::create_directories(folder.file("full"));
    ASSERT_EQ(run_clrender("anim.json -q -o 'full/f_%04d.png' --video full/video.mp4", folder.path()).exit_code, 0);
    std::string command = "cd '" + folder.path() + "' && CLRENDER='" + CLRENDER_BINARY + "' bash '" +
                          CLRENDER_SOURCE_DIR + "/scripts/render_parallel.sh' anim.json farm 2 > farm.log 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << read_bytes(folder.file("farm.log"));
    for (int frame = 0; frame < 11; ++frame) {
        char name[32];
        std::snprintf(name, sizeof name, "farm/frame_%04d.png", frame);
        EXPECT_EQ(read_bytes(folder.file(name)), read_bytes(folder.file("full/" + frame_name(frame)))) << name;
    }
    EXPECT_EQ(read_bytes(folder.file("farm/video.mp4")), read_bytes(folder.file("full/video.mp4")))
        << "assembling the same frames gives the same video";
}

TEST_F(AnimationCli, MissingEncoderIsDetectedBeforeRendering) {
    auto result = run_clrender("anim.json -o 'f_%04d.png' --video out.mp4", folder.path(), "CLRENDER_FFMPEG=/nonexistent/ffmpeg");
    EXPECT_EQ(result.exit_code, 4);
    EXPECT_NE(result.output.find("/nonexistent/ffmpeg"), std::string::npos) << result.output;
    EXPECT_FALSE(fs::exists(folder.file(frame_name(0)))) << "nothing may render before the encoder is found";
    EXPECT_FALSE(fs::exists(folder.file("out.mp4")));
}

TEST_F(AnimationCli, FailingEncoderExitsWith4AndLeavesNoVideo) {
    folder.write("bad-ffmpeg", "#!/bin/sh\ncat > /dev/null\necho 'encoder exploded' >&2\nexit 1\n");
    fs::permissions(folder.file("bad-ffmpeg"), fs::perms::owner_all);
    auto result = run_clrender("anim.json -q --video out.mp4", folder.path(), "CLRENDER_FFMPEG=" + folder.file("bad-ffmpeg"));
    EXPECT_EQ(result.exit_code, 4);
    EXPECT_NE(result.output.find("encoder exploded"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("out.mp4"), std::string::npos) << result.output;
    for (const auto& entry : fs::directory_iterator(folder.path())) {
        std::string name = entry.path().filename().string();
        EXPECT_TRUE(name == "anim.json" || name == "bad-ffmpeg") << "left behind: " << name;
    }
}

TEST_F(AnimationCli, AssemblingReportsAMissingFrame) {
    ASSERT_EQ(run_clrender("anim.json -q --frames 0-4 -o 'f_%04d.png'", folder.path()).exit_code, 0);
    auto result = run_clrender("anim.json -q --assemble -o 'f_%04d.png' --video out.mp4", folder.path());
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.output.find(frame_name(5)), std::string::npos) << result.output;
    EXPECT_FALSE(fs::exists(folder.file("out.mp4")));
}

TEST_F(AnimationCli, ContradictoryRequestsAreUsageErrors) {
    folder.write("still.json", R"({"eye": [0, 0, 5], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
                                   "width": 8, "height": 8})");
    EXPECT_EQ(run_clrender("anim.json -o plain.png", folder.path()).exit_code, 1);
    EXPECT_EQ(run_clrender("still.json --video still.mp4", folder.path()).exit_code, 1);
    EXPECT_EQ(run_clrender("anim.json --frames 11", folder.path()).exit_code, 1);
    EXPECT_EQ(run_clrender("anim.json --frames 2-1", folder.path()).exit_code, 1);
    EXPECT_EQ(run_clrender("anim.json --video out.avi", folder.path()).exit_code, 1);
    EXPECT_EQ(run_clrender("anim.json --assemble --video out.mp4", folder.path()).exit_code, 1);
    EXPECT_EQ(run_clrender("anim.json --quality 99", folder.path()).exit_code, 1);
    EXPECT_FALSE(fs::exists(folder.file("anim.mp4")));
}

}  // namespace
}  // namespace clr
