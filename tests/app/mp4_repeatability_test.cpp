// The same frames give the same MP4 bytes however the encoder's threads happen to be
// scheduled: on one CPU (a farm's 1-CPU final job, `taskset`) and on every CPU, encode after
// encode (docs/animation.md, MP4 encoding). x264's own lookahead thread made the bytes depend on
// scheduling. The command itself must not depend on the machine either.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "support/command.h"
#include "support/cpu_affinity.h"
#include "support/shell.h"
#include "support/small_disk.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

using testing::first_usable_cpu;
using testing::have_program;
using testing::read_bytes;
using testing::run_clrender;
using testing::run_shell;
using testing::shell_quoted;
using testing::TempFolder;

// The demo flight at a small size: a moving camera over textures, shadows and a mirror. Its
// encodes differed while x264 ran its lookahead on a thread of its own; made-up frames
// (gradients, noise, cuts, ffmpeg's test sources) never did.
const char* kRender = "--size 320x180 --spp 4";

// x264's races showed most when ffmpeg read the frames from a file, as fast as x264 took them:
// 9 of 20 encodes of these frames differed from the usual video, against 1 of 20 read from a
// pipe, as clrender feeds them. So clrender's own video is compared with its ffmpeg command
// run again on the frames it sent, read from a file. With the lookahead thread 2 to 7 of these
// ten encodes differed, in each of five runs; ten alike by chance was about 1 in 400.
constexpr int kEncodes = 10;

// The lines of `text`.
std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream stream(text);
    for (std::string line; std::getline(stream, line);) lines.push_back(line);
    return lines;
}

// An encoder in `folder` that records its arguments, one a line, into `arguments_file` and
// the frames it is sent into frames.yuv, then runs ffmpeg on them. Returns the environment
// assignment that makes clrender use it.
std::string recording_encoder(const TempFolder& folder, const std::string& arguments_file) {
    folder.write("recording-ffmpeg", "#!/bin/sh\nprintf '%s\\n' \"$@\" > '" + folder.file(arguments_file) +
                                         "'\ntee '" + folder.file("frames.yuv") + "' | exec ffmpeg \"$@\"\n");
    ::chmod(folder.file("recording-ffmpeg").c_str(), 0755);
    return "CLRENDER_FFMPEG=" + shell_quoted(folder.file("recording-ffmpeg"));
}

TEST(Mp4Repeatability, SameFramesGiveOneVideoOnOneCpuAndOnEvery) {
    if (!have_program("ffmpeg") || !have_program("ffprobe") || !have_program("taskset"))
        GTEST_SKIP() << "ffmpeg or taskset is not installed";
    TempFolder folder;
    const std::string scene = std::string(CLRENDER_SOURCE_DIR) + "/scenes/demo/showcase.json";
    const auto result = run_clrender("'" + scene + "' -q " + kRender + " --video one.mp4", folder.path(),
                                     recording_encoder(folder, "arguments"));
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const std::string video = read_bytes(folder.file("one.mp4"));
    ASSERT_FALSE(video.empty());

    // clrender's command line with the frames read from the file and another output.
    std::vector<std::string> arguments = lines_of(read_bytes(folder.file("arguments")));
    ASSERT_GT(arguments.size(), 3u);
    const auto input = std::find(arguments.begin(), arguments.end(), "-i");
    ASSERT_TRUE(input != arguments.end() && input + 1 != arguments.end() && *(input + 1) == "-");
    *(input + 1) = folder.file("frames.yuv");
    for (int round = 0; round < kEncodes; ++round) {
        const bool one_cpu = round % 2 == 0;
        arguments.back() = folder.file("again.mp4");
        std::string command = one_cpu ? "taskset -c " + std::to_string(first_usable_cpu()) + " ffmpeg" : "ffmpeg";
        for (const std::string& argument : arguments) command += " " + shell_quoted(argument);
        const auto encoded = run_shell(command);
        ASSERT_EQ(encoded.exit_code, 0) << command << "\n" << encoded.output;
        EXPECT_TRUE(read_bytes(folder.file("again.mp4")) == video)  // no EXPECT_EQ: it would print the videos
            << "encode " << round << (one_cpu ? " on one CPU" : " on every CPU")
            << " gave other bytes than clrender's video";
    }
}

// The encoder's command line is the same whatever CPUs clrender may use: nothing in it (x264's
// thread count, its options) is taken from the machine, which would give a farm's 1-CPU node
// other bytes than a desktop.
TEST(Mp4Repeatability, TheEncodersCommandIsTheSameOnOneCpu) {
    if (!have_program("ffmpeg") || !have_program("ffprobe") || !have_program("taskset"))
        GTEST_SKIP() << "ffmpeg or taskset is not installed";
    TempFolder folder;
    folder.write("anim.json", R"({
      "eyeLocations": [[-3, 1, 8], [3, 2, 7]], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 55,
      "width": 64, "height": 48, "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0.3, 0.2]}]
    })");
    auto result = run_clrender("anim.json -q --video every.mp4", folder.path(), recording_encoder(folder, "every"));
    ASSERT_EQ(result.exit_code, 0) << result.output;
    result = run_clrender("anim.json -q --video one.mp4", folder.path(),
                          recording_encoder(folder, "one") + " taskset -c " + std::to_string(first_usable_cpu()));
    ASSERT_EQ(result.exit_code, 0) << result.output;
    std::vector<std::string> every = lines_of(read_bytes(folder.file("every")));
    std::vector<std::string> one = lines_of(read_bytes(folder.file("one")));
    ASSERT_FALSE(every.empty());
    ASSERT_FALSE(one.empty());
    // The last is the temporary file the video is written to, another name in each run.
    every.pop_back();
    one.pop_back();
    EXPECT_EQ(one, every);
    EXPECT_NE(std::find(every.begin(), every.end(), "-threads"), every.end());
}

}  // namespace
}  // namespace clr
