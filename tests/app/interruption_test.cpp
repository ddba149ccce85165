// Ctrl-C or SIGTERM in the middle of an animation: a clean exit with 128 + signal, complete
// frames kept, nothing partial under a final name, and a rerun with --resume finishing the
// job with the same frames as an uninterrupted run.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

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

TEST(Interruption, ResumeNeedsAFramePattern) {
    TempFolder folder;
    folder.write("anim.json", kLongAnimation);
    EXPECT_EQ(run_clrender("anim.json --resume --video x.mp4", folder.path()).exit_code, 1);
}

}  // namespace
}  // namespace clr
