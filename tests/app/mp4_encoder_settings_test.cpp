// The x264 settings clrender chooses for an MP4 (docs/animation.md, MP4 encoding), read back
// from the settings x264 writes into every stream it encodes: preset veryfast, and half the
// CPUs clrender may use as threads (at least one).
#include <gtest/gtest.h>
#include <sched.h>

#include <algorithm>
#include <string>

#include "support/command.h"
#include "support/small_disk.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

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

int usable_cpus() {
    cpu_set_t allowed;
    return ::sched_getaffinity(0, sizeof(allowed), &allowed) == 0 ? CPU_COUNT(&allowed) : 0;
}

// The first CPU this process may run on.
int first_usable_cpu() {
    cpu_set_t allowed;
    if (::sched_getaffinity(0, sizeof(allowed), &allowed) != 0) return 0;
    int cpu = 0;
    while (cpu < CPU_SETSIZE && !CPU_ISSET(cpu, &allowed)) ++cpu;
    return cpu;
}

TEST(Mp4EncoderSettings, PresetVeryfastWithHalfTheUsableCpus) {
    if (!have_program("ffmpeg") || !have_program("ffprobe")) GTEST_SKIP() << "ffmpeg is not installed";
    TempFolder folder;
    folder.write("anim.json", kAnimatedScene);
    // Large enough that x264 would run more threads by itself (it runs fewer on small frames).
    const auto result = run_clrender("anim.json -q --quality 20 --size 320x240", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const std::string settings = x264_settings(folder.file("anim.mp4"));
    ASSERT_FALSE(settings.empty()) << "no x264 settings in the video";
    // What x264's veryfast preset sets (medium: ref=3, subme=7, trellis=1, rc_lookahead=40).
    for (const char* setting : {" ref=1 ", " subme=2 ", " me=hex ", " trellis=0 ", " rc_lookahead=10 ", " crf=20.0 "})
        EXPECT_NE(settings.find(setting), std::string::npos) << setting << " not in" << settings;
    const int cpus = usable_cpus();
    ASSERT_GT(cpus, 0);
    const std::string threads = " threads=" + std::to_string(std::max(1, cpus / 2)) + " ";
    EXPECT_NE(settings.find(threads), std::string::npos) << threads << " not in" << settings;
}

// Under `taskset` (or a Slurm task's cpuset) x264 counts only the CPUs clrender may use.
TEST(Mp4EncoderSettings, OneUsableCpuGivesOneThread) {
    if (!have_program("ffmpeg") || !have_program("ffprobe") || !have_program("taskset"))
        GTEST_SKIP() << "ffmpeg or taskset is not installed";
    TempFolder folder;
    folder.write("anim.json", kAnimatedScene);
    const auto result = run_clrender("anim.json -q", folder.path(), "taskset -c " + std::to_string(first_usable_cpu()));
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const std::string settings = x264_settings(folder.file("anim.mp4"));
    EXPECT_NE(settings.find(" threads=1 "), std::string::npos) << settings;
}

}  // namespace
}  // namespace clr
