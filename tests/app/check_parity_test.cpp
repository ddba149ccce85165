// --check and --plan refuse exactly what a render refuses without a device, with the render's
// message and exit code (docs/command-line.md, Checking a scene; Planning a run): each bad
// command of the table is run as a render (with --reference, so that no refusal waits for a
// device), with --check and with --plan, and each must fail alike and leave the folder as it
// was.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "output/temp_files.h"
#include "support/command.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::run_clrender;
using testing::TempFolder;

// An animation of 6 frames and a still, both tiny.
const char* kAnimation = R"({
  "eyeLocations": [[0, 0, 6], [1, 0, 6]], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
  "width": 16, "height": 12, "clrender": {"fps": 6, "frames": 6},
  "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0, 0]}]
})";
const char* kStill = R"({
  "eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60, "width": 16, "height": 12,
  "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0, 0]}]
})";

struct BadCommand {
    const char* arguments;
    int exit_code;        // the render's, checked independently of --check's
    const char* message;  // a part of the render's message
    bool planned = true;  // false: refused only when the run reads files back, which --plan does not
    const char* environment = "";
};

const std::vector<BadCommand> kBadCommands = {
    {"anim.json -o one.png", 1, "the animation has 6 frames to write; give a frame pattern"},
    {"anim.json -o 'a#b/f.png' --frames 0-2", 1, "-o a#b/f.png: the animation has 3 frames to write"},
    {"anim.json -o 'f_%100d.png' --frames 0-2", 1, "the animation has 3 frames to write"},
    {"still.json --video v.mp4", 1, "is a still (one camera key); a video needs eyeLocations"},
    {"anim.json --alpha --video v.mp4", 1, "--alpha: the video v.mp4 would have no alpha channel"},
    {"anim.json --alpha -o 'f_%04d.ppm'", 1, "is a PPM, which has no alpha channel"},
    {"anim.json --frames 0-20 -o 'f_%04d.png'", 1, "frame 20 is out of range: the animation has 6 frames"},
    {"anim.json --frames 5- -o 'f_%04d.png'", 1, "'5-' is not a frame number or range"},
    {"anim.json --assemble -o 'f_%04d.exr' --video v.mp4", 1, "EXR frames cannot be read back into a video"},
    {"anim.json --resume --video v.mp4", 1, "--resume needs -o with a frame pattern"},
    {"anim.json --assemble --video v.mp4", 1, "--assemble needs -o with the frame pattern"},
    {"anim.json --video v.avi", 1, "v.avi"},
    {"still.json -o s.bmp", 1, "s.bmp"},
    {"still.json -o -", 1, "-o -: clrender writes images and videos only to files"},
    {"still.json --crop 0,20,0,5", 1, "--crop 0,20,0,5 reaches outside the 16x12 image"},
    {"still.json --join t.png -o 'x_%04d.png'", 1, "--join makes one image"},
    {"still.json --stats still.json", 4, "still.json"},
    {"still.json -o file.txt/x.png", 4, "file.txt/x.png"},
    {"still.json -o s.png --stats s.png", 4, "s.png"},
    {"anim.json --video v.mp4 --frames 1", 4, "no-such-ffmpeg", true, "CLRENDER_FFMPEG=no-such-ffmpeg"},
    {"anim.json --video v.mp4 --frames 1", 4, "no-such-ffprobe", true, "CLRENDER_FFPROBE=no-such-ffprobe"},
    {"anim.json --video v.gif", 1, "CLRENDER_ENCODER_TIMEOUT must be a number", true, "CLRENDER_ENCODER_TIMEOUT=soon"},
    {"cut.json", 2, "cut.png"},
    {"still.json --join missing.png", 2, "missing.png", false},
    {"anim.json --assemble -o 'f_%04d.png' --video v.mp4", 2, "f_0000.png", false},
};

std::set<std::string> entries_of(const std::string& folder) {
    std::set<std::string> names;
    for (const auto& entry : fs::recursive_directory_iterator(folder)) names.insert(entry.path().string());
    return names;
}

TEST(CheckParity, CheckAndPlanRefuseWhatTheRenderRefusesWithItsMessageAndExitCode) {
    TempFolder folder;
    folder.write("anim.json", kAnimation);
    folder.write("still.json", kStill);
    folder.write("file.txt", "a file, not a folder\n");
    // A PNG whose header is whole and whose pixel data is cut off.
    const std::string png = read_bytes(fs::path(CLRENDER_SOURCE_DIR) / "scenes/demo/backdrop.png");
    folder.write("cut.png", png.substr(0, png.size() / 2));
    folder.write("cut.json", R"({"eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
      "width": 8, "height": 6, "billboards": [{"UpperLeft": [-1, 1, 0], "LowerLeft": [-1, -1, 0],
      "UpperRight": [1, 1, 0], "filename": "cut.png"}]})");
    const std::set<std::string> before = entries_of(folder.path());
    for (const BadCommand& bad : kBadCommands) {
        SCOPED_TRACE(std::string(bad.environment) + " " + bad.arguments);
        const auto render = run_clrender(std::string(bad.arguments) + " -q --reference", folder.path(), bad.environment);
        ASSERT_EQ(render.exit_code, bad.exit_code) << render.output;
        ASSERT_NE(render.output.find(bad.message), std::string::npos) << render.output;
        EXPECT_EQ(entries_of(folder.path()), before) << "the refused render changed the folder";
        const auto check = run_clrender(std::string(bad.arguments) + " -q --reference --check", folder.path(), bad.environment);
        EXPECT_EQ(check.exit_code, render.exit_code) << check.output;
        EXPECT_EQ(check.output, render.output);
        EXPECT_EQ(entries_of(folder.path()), before) << "--check changed the folder";
        const auto plan = run_clrender(std::string(bad.arguments) + " -q --reference --plan", folder.path(), bad.environment);
        if (bad.planned) {
            EXPECT_EQ(plan.exit_code, render.exit_code) << plan.output;
            EXPECT_EQ(plan.output, render.output);
        } else {
            EXPECT_EQ(plan.exit_code, 0) << "--plan reads no frames or tiles back:\n" << plan.output;
        }
        EXPECT_EQ(entries_of(folder.path()), before) << "--plan changed the folder";
    }
}

// The explainer's checks are a render's too; --plan, which plans files, excludes it.
TEST(CheckParity, CheckRefusesAPixelOutsideTheImageAsTheExplainerDoes) {
    TempFolder folder;
    folder.write("still.json", kStill);
    const auto explain = run_clrender("still.json --reference --explain-pixel 16,0", folder.path());
    ASSERT_EQ(explain.exit_code, 1) << explain.output;
    ASSERT_NE(explain.output.find("--explain-pixel 16,0 is outside the 16x12 image"), std::string::npos) << explain.output;
    const auto check = run_clrender("still.json --reference --explain-pixel 16,0 --check", folder.path());
    EXPECT_EQ(check.exit_code, 1);
    EXPECT_EQ(check.output, explain.output);
    const auto plan = run_clrender("still.json --explain-pixel 1,1 --plan", folder.path());
    EXPECT_EQ(plan.exit_code, 1);
    EXPECT_NE(plan.output.find("--plan excludes --explain-pixel"), std::string::npos) << plan.output;
}

// --kernel-dir's files are read before a device builds them: a folder without them fails the
// check as it fails a render on a device.
TEST(CheckParity, CheckFindsAKernelFolderWithoutTheKernels) {
    TempFolder folder;
    folder.write("still.json", kStill);
    fs::create_directories(folder.file("kernels"));
    const auto render = run_clrender("still.json -q --kernel-dir kernels -o s.png", folder.path());
    if (render.output.find("no OpenCL device") != std::string::npos) GTEST_SKIP() << "no OpenCL device here";
    ASSERT_EQ(render.exit_code, 3) << render.output;
    ASSERT_NE(render.output.find("render_tiles.cl"), std::string::npos) << render.output;
    for (const char* mode : {"--check", "--plan"}) {
        const auto check = run_clrender(std::string("still.json -q --kernel-dir kernels -o s.png ") + mode, folder.path());
        EXPECT_EQ(check.exit_code, 3) << mode;
        EXPECT_EQ(check.output, render.output) << mode;
    }
    // The project's own kernels pass.
    const std::string kernels = std::string(CLRENDER_SOURCE_DIR) + "/kernels";
    EXPECT_EQ(run_clrender("still.json --kernel-dir '" + kernels + "' --check", folder.path()).exit_code, 0);
}

// A check leaves no file behind, not even the temporary files of a crashed run that a render
// would sweep away: it changes nothing.
TEST(CheckParity, CheckAndPlanLeaveEveryFileAsItWas) {
    TempFolder folder;
    folder.write("still.json", kStill);
    fs::create_directories(folder.file("out"));
    // A stale temporary file of clrender's form (this machine's, a process id that cannot be alive).
    const std::string stale = "out/.clrender-" + temp_host_id() + "-999999999-1.tmp";
    folder.write(stale, "left by a killed run");
    for (const char* mode : {"--check", "--plan"}) {
        const auto result = run_clrender(std::string("still.json -o out/s.png ") + mode, folder.path());
        EXPECT_EQ(result.exit_code, 0) << result.output;
        EXPECT_TRUE(fs::exists(folder.file(stale))) << mode << " removed a file";
        EXPECT_FALSE(fs::exists(folder.file("out/s.png")));
    }
    EXPECT_EQ(entries_of(folder.path()).size(), 3u);  // still.json, out, the stale file
    // The file is one that a render removes.
    ASSERT_EQ(run_clrender("still.json -o out/s.png -q --reference", folder.path()).exit_code, 0);
    EXPECT_FALSE(fs::exists(folder.file(stale)));
}

}  // namespace
}  // namespace clr
