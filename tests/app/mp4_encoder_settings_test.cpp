// The x264 settings clrender chooses for an MP4 (docs/animation.md, MP4 encoding), read back
// from the settings x264 writes into every stream it encodes: preset veryfast, and 4 threads on
// every machine, so that the same frames give the same bytes wherever they are encoded.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "support/command.h"
#include "support/cpu_affinity.h"
#include "support/small_disk.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

using testing::first_usable_cpu;
using testing::have_program;
using testing::read_bytes;
using testing::run_clrender;
using testing::TempFolder;

const char* kAnimatedScene = R"({
  "eyeLocations": [[-3, 1, 8], [3, 2, 7]], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 55,
  "width": 64, "height": 48, "DefaultColor": [0.1, 0.1, 0.2],
  "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0.3, 0.2]}]
})";

// x264's settings line in the video ("cabac=1 ref=1 ... crf=18.0 ..."), or empty.
std::string x264_settings(const std::string& video) {
    const std::string bytes = read_bytes(video);
    const std::size_t start = bytes.find("x264 - core");
    if (start == std::string::npos) return "";
    const std::size_t options = bytes.find("options: ", start);
    const std::size_t end = bytes.find('\0', options);
    return " " + bytes.substr(options + 9, end - options - 9) + " ";
}

TEST(Mp4EncoderSettings, PresetVeryfastWithFourThreads) {
    if (!have_program("ffmpeg") || !have_program("ffprobe")) GTEST_SKIP() << "ffmpeg is not installed";
    TempFolder folder;
    folder.write("anim.json", kAnimatedScene);
    // Not the scene's 64x48: x264's settings are read back from a frame of a usual shape.
    const auto result = run_clrender("anim.json -q --quality 20 --size 320x240", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const std::string settings = x264_settings(folder.file("anim.mp4"));
    ASSERT_FALSE(settings.empty()) << "no x264 settings in the video";
    // What x264's veryfast preset sets (medium: ref=3, subme=7, trellis=1, rc_lookahead=40).
    for (const char* setting : {" ref=1 ", " subme=2 ", " me=hex ", " trellis=0 ", " rc_lookahead=10 ", " crf=20.0 "})
        EXPECT_NE(settings.find(setting), std::string::npos) << setting << " not in" << settings;
    EXPECT_NE(settings.find(" threads=4 "), std::string::npos) << settings;
    EXPECT_NE(settings.find(" sliced_threads=0 "), std::string::npos) << settings;  // frame threads
}

// Under `taskset` (or a Slurm task's cpuset, a farm's 1-CPU node) x264 gets the same threads,
// and the video is the same bytes as one made with every CPU.
TEST(Mp4EncoderSettings, OneUsableCpuGivesTheSameThreadsAndBytes) {
    if (!have_program("ffmpeg") || !have_program("ffprobe") || !have_program("taskset"))
        GTEST_SKIP() << "ffmpeg or taskset is not installed";
    TempFolder folder;
    folder.write("anim.json", kAnimatedScene);
    // Large enough for x264's threads to encode different frames at once.
    auto result = run_clrender("anim.json -q --size 320x240 --video every_cpu.mp4", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    result = run_clrender("anim.json -q --size 320x240 --video one_cpu.mp4", folder.path(),
                          "taskset -c " + std::to_string(first_usable_cpu()));
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const std::string settings = x264_settings(folder.file("one_cpu.mp4"));
    EXPECT_NE(settings.find(" threads=4 "), std::string::npos) << settings;
    const std::string every_cpu = read_bytes(folder.file("every_cpu.mp4"));
    EXPECT_FALSE(every_cpu.empty());
    EXPECT_TRUE(every_cpu == read_bytes(folder.file("one_cpu.mp4")))  // no EXPECT_EQ: it would print the videos
        << "one usable CPU gave other bytes than every CPU";
}

}  // namespace
}  // namespace clr
