// Ctrl-C or SIGTERM in the middle of an animation: a clean exit with 128 + signal, complete
// frames kept, nothing partial under a final name, and a rerun with --resume finishing the
// job with the same frames as an uninterrupted run. In the middle of one long still: the
// same exit within a second (bands of rows, and the reference's rows, check for the signal),
// no image, and an earlier image under the output name untouched.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "support/command.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::frame_name;
using testing::run_clrender;
using testing::TempFolder;

// 1001 small frames: long enough to interrupt, quick to finish.
const char* kLongAnimation = R"({
  "eyeLocations": [[-3, 1, 8], [3, 2, 7]], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 55,
  "width": 48, "height": 32, "clrender": {"frames": 1001},
  "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0.3, 0.2]}],
  "billboards": [{"UpperLeft": [-5, 4, -4], "LowerLeft": [-5, -3, -4], "UpperRight": [5, 4, -4], "ambient": [0.2, 0.6, 0.3]}]
})";

// Starts clrender in the background, waits until frame 20 exists, sends `signal_name`, and
// returns clrender's exit code.
int interrupt_run(const TempFolder& folder, const std::string& arguments, const std::string& signal_name) {
    folder.write("interrupt.sh", "cd '" + folder.path() + "'\n'" + CLRENDER_BINARY + "' " + arguments +
                                     " 2> stderr.txt &\n"
                                     "pid=$!\n"
                                     "i=0\n"
                                     "while [ ! -e " + frame_name(20) + " ] && [ $i -lt 3000 ]; do sleep 0.01; i=$((i+1)); done\n"
                                     "kill -" + signal_name + " $pid\n"
                                     "wait $pid\n"
                                     "echo $? > code.txt\n");
    if (std::system(("bash '" + folder.file("interrupt.sh") + "'").c_str()) != 0) return -1;
    return std::stoi(read_bytes(folder.file("code.txt")));
}

void expect_only_complete_outputs(const TempFolder& folder) {
    int frames = 0;
    for (const auto& entry : fs::directory_iterator(folder.path())) {
        std::string name = entry.path().filename().string();
        if (name.rfind("f_", 0) == 0) {
            ++frames;
            continue;
        }
        EXPECT_TRUE(name == "anim.json" || name == "stderr.txt" || name == "code.txt" || name == "interrupt.sh") << "left behind: " << name;
    }
    EXPECT_GE(frames, 21);
    EXPECT_LT(frames, 1001) << "the run should have been interrupted";
    for (int frame = 0; frame < frames; ++frame) EXPECT_TRUE(fs::exists(folder.file(frame_name(frame)))) << frame;
}

TEST(Interruption, SigtermStopsCleanlyAndResumeFinishesTheJob) {
    TempFolder folder;
    folder.write("anim.json", kLongAnimation);
    int code = interrupt_run(folder, "anim.json -q -o 'f_%04d.png' --video anim.mp4", "TERM");
    EXPECT_EQ(code, 128 + 15) << read_bytes(folder.file("stderr.txt"));
    EXPECT_NE(read_bytes(folder.file("stderr.txt")).find("interrupted by SIGTERM"), std::string::npos);
    EXPECT_FALSE(fs::exists(folder.file("anim.mp4"))) << "an interrupted video must not appear";
    expect_only_complete_outputs(folder);

    auto resumed = run_clrender("anim.json -q -o 'f_%04d.png' --video anim.mp4 --resume --stats stats.json", folder.path());
    ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
    EXPECT_TRUE(fs::exists(folder.file("anim.mp4")));
    EXPECT_TRUE(fs::exists(folder.file(frame_name(1000))));
    std::string stats = read_bytes(folder.file("stats.json"));
    EXPECT_EQ(stats.find("\"index\": 0,"), std::string::npos) << "frame 0 was written before: not rendered again";

    // The frames of the interrupted-and-resumed run equal an uninterrupted run's.
    fs::create_directories(folder.file("full"));
    ASSERT_EQ(run_clrender("anim.json -q --frames 0,20,21,1000 -o 'full/f_%04d.png'", folder.path()).exit_code, 0);
    for (int frame : {0, 20, 21, 1000})
        EXPECT_EQ(read_bytes(folder.file(frame_name(frame))), read_bytes(folder.file("full/" + frame_name(frame)))) << frame;
}

TEST(Interruption, CtrlCExitsWith130) {
    TempFolder folder;
    folder.write("anim.json", kLongAnimation);
    int code = interrupt_run(folder, "anim.json -q -o 'f_%04d.png'", "INT");
    EXPECT_EQ(code, 128 + 2) << read_bytes(folder.file("stderr.txt"));
    expect_only_complete_outputs(folder);
}

// A still that takes minutes in one launch on two CPU cores (and seconds on a large GPU):
// mirrors, sun and shadows, many samples per pixel.
const char* kSlowStill = R"({
  "eye": [0, 3, 14], "lookat": [0, 1, 0], "up": [0, 1, 0], "fov_angle": 60,
  "width": 64, "height": 64, "SunLocation": [30, 50, 20], "MaxDepth": 8,
  "spheres": [
    {"center": [-3, 1, 0], "radius": 2, "ambient": [0.9, 0.3, 0.2], "IsMirror": 1},
    {"center": [3, 1, 0], "radius": 2, "ambient": [0.2, 0.4, 0.9], "IsMirror": 1},
    {"center": [0, 1, -4], "radius": 2, "ambient": [0.3, 0.8, 0.3], "IsMirror": 1},
    {"center": [0, 4, 2], "radius": 1, "ambient": [0.9, 0.9, 0.2]}],
  "billboards": [{"UpperLeft": [-20, -1, -20], "LowerLeft": [-20, -1, 20], "UpperRight": [20, -1, -20], "ambient": [0.5, 0.5, 0.5]}]
})";
const char* kEarlierImage = "an image written by an earlier run";

struct StopResult {
    int exit_code = -1;
    double stop_seconds = -1;  // from the signal to clrender's exit
};

// Starts `clrender still.json -o still.png <arguments>`, waits until it has opened its device
// (it is rendering then), sends `signal_name` and measures how long clrender takes to exit.
StopResult interrupt_still(const TempFolder& folder, const std::string& arguments, const std::string& signal_name) {
    folder.write("still.json", kSlowStill);
    folder.write("still.png", kEarlierImage);
    folder.write("interrupt.sh", "cd '" + folder.path() + "'\n'" + CLRENDER_BINARY + "' still.json -o still.png " +
                                     arguments + " 2> stderr.txt &\n"
                                     "pid=$!\n"
                                     "i=0\n"
                                     "until grep -q 'clrender: device' stderr.txt || [ $i -ge 1200 ]; do sleep 0.05; i=$((i+1)); done\n"
                                     "sleep 1.5\n"  // bands at their full length by then
                                     "start=$(date +%s%N)\n"
                                     "kill -" + signal_name + " $pid\n"
                                     "wait $pid\n"
                                     "code=$?\n"
                                     "end=$(date +%s%N)\n"
                                     "echo $code $(( (end - start) / 1000000 )) > result.txt\n");
    StopResult result;
    if (std::system(("bash '" + folder.file("interrupt.sh") + "'").c_str()) != 0) return result;
    std::istringstream(read_bytes(folder.file("result.txt"))) >> result.exit_code >> result.stop_seconds;
    result.stop_seconds /= 1000;
    // The real figure, for the record; the assertion below allows for a loaded machine.
    std::cout << "clrender stopped " << result.stop_seconds << " s after SIG" << signal_name << "\n";
    return result;
}

void expect_still_stopped(const TempFolder& folder, const StopResult& result, int signal_number) {
    std::string stderr_text = read_bytes(folder.file("stderr.txt"));
    EXPECT_EQ(result.exit_code, 128 + signal_number) << stderr_text;
    EXPECT_LT(result.stop_seconds, 5.0) << "the promise is one second; this allows for a loaded machine";
    EXPECT_NE(stderr_text.find("clrender: error:"), std::string::npos) << stderr_text;
    EXPECT_TRUE(read_bytes(folder.file("still.png")) == kEarlierImage) << "the earlier image must stay";
    for (const auto& entry : fs::directory_iterator(folder.path())) {
        std::string name = entry.path().filename().string();
        EXPECT_TRUE(name == "still.json" || name == "still.png" || name == "stderr.txt" || name == "interrupt.sh" ||
                    name == "result.txt")
            << "left behind: " << name;
    }
}

TEST(Interruption, CtrlCStopsALongStillWithinASecond) {
    TempFolder folder;
    StopResult result = interrupt_still(folder, "--size 2048x2048 --spp 256", "INT");
    expect_still_stopped(folder, result, 2);
}

TEST(Interruption, SigtermStopsALongStillWithinASecond) {
    TempFolder folder;
    StopResult result = interrupt_still(folder, "--size 2048x2048 --spp 256", "TERM");
    expect_still_stopped(folder, result, 15);
}

TEST(Interruption, CtrlCStopsALongReferenceStillWithinASecond) {
    TempFolder folder;
    StopResult result = interrupt_still(folder, "--reference --size 1024x1024 --spp 64", "INT");
    expect_still_stopped(folder, result, 2);
}

// A closed terminal (SIGHUP) stops clrender as SIGTERM does, instead of killing it mid-write.
TEST(Interruption, SighupStopsALongReferenceStillCleanly) {
    TempFolder folder;
    StopResult result = interrupt_still(folder, "--reference --size 1024x1024 --spp 64", "HUP");
    expect_still_stopped(folder, result, 1);
    EXPECT_NE(read_bytes(folder.file("stderr.txt")).find("interrupted by SIGHUP"), std::string::npos);
}

TEST(Interruption, ResumeNeedsAFramePattern) {
    TempFolder folder;
    folder.write("anim.json", kLongAnimation);
    EXPECT_EQ(run_clrender("anim.json --resume --video x.mp4", folder.path()).exit_code, 1);
}

}  // namespace
}  // namespace clr
