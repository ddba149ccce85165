// --plan through the real binary (docs/command-line.md, Planning a run): the JSON names the
// frames, the image size, every file the run writes and how it splits, as the render then does
// it; nothing is written and no OpenCL platform is opened.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/command.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using testing::run_clrender;
using testing::TempFolder;

const char* kAnimation = R"({
  "eyeLocations": [[0, 0, 6], [1, 0, 6]], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
  "width": 16, "height": 12, "clrender": {"fps": 6, "frames": 12},
  "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0, 0]}]
})";
const char* kStill = R"({
  "eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60, "width": 30, "height": 20,
  "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0, 0]}]
})";

json plan_of(const std::string& arguments, const TempFolder& folder, const std::string& environment = "") {
    const auto result = run_clrender(arguments + " --plan", folder.path(), environment);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return json::parse(result.output);
}

std::vector<std::string> paths_of(const json& images) {
    std::vector<std::string> paths;
    for (const json& image : images) paths.push_back(image["path"]);
    return paths;
}

TEST(PlanCli, AnAnimationsPlanNamesEachFrameFileAndTheVideoAndTheRenderWritesThem) {
    TempFolder folder;
    folder.write("anim.json", kAnimation);
    const std::string command = "anim.json --frames 2,5-6 -o 'out/f_%03d.png' --video v.gif";
    const json plan = plan_of(command, folder);
    EXPECT_FALSE(fs::exists(folder.file("out"))) << "--plan made the output folder";
    EXPECT_EQ(plan["still"], false);
    EXPECT_EQ(plan["frame_count"], 12);
    EXPECT_EQ(plan["frames"], json({2, 5, 6}));
    EXPECT_EQ(plan["frame_pattern"], "out/f_%03d.png");
    EXPECT_EQ(plan["video"], "v.gif");
    const std::vector<std::string> frames = {"out/f_002.png", "out/f_005.png", "out/f_006.png"};
    EXPECT_EQ(paths_of(plan["images"]), frames);
    EXPECT_EQ(plan["writes"], json({"out/f_002.png", "out/f_005.png", "out/f_006.png", "v.gif"}));
    EXPECT_EQ(plan["split"], json({{"by", "frames"}, {"frames", {2, 5, 6}}}));
    EXPECT_EQ(plan["width"], 16);
    EXPECT_EQ(plan["height"], 12);
    // The render writes exactly the planned files.
    ASSERT_EQ(run_clrender(command + " -q --reference", folder.path()).exit_code, 0);
    for (const std::string& frame : frames) EXPECT_TRUE(fs::is_regular_file(folder.file(frame))) << frame;
    EXPECT_TRUE(fs::is_regular_file(folder.file("v.gif")));
    int files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(folder.path())) files += entry.is_regular_file();
    EXPECT_EQ(files, 5);  // the scene, three frames, the video
}

// Names that look like patterns to a regular expression but not to clrender: a '#' in a
// folder, a three-digit width. The plan says what clrender writes: one file.
TEST(PlanCli, OnlyTheFileNamesPlaceholderMakesAFramePattern) {
    TempFolder folder;
    folder.write("anim.json", kAnimation);
    for (const std::string output : {"a#b/f.png", "f_%100d.png", "x%/f.png"}) {
        SCOPED_TRACE(output);
        const json plan = plan_of("anim.json --frames 3 -o '" + output + "'", folder);
        EXPECT_EQ(plan["frame_pattern"], nullptr);
        EXPECT_EQ(paths_of(plan["images"]), std::vector<std::string>{output});
        EXPECT_EQ(plan["video"], nullptr);
    }
    const json blender = plan_of("anim.json --frames 3,11 -o 'a#b/f_###.png'", folder);
    EXPECT_EQ(blender["frame_pattern"], "a#b/f_###.png");
    EXPECT_EQ(paths_of(blender["images"]), (std::vector<std::string>{"a#b/f_003.png", "a#b/f_011.png"}));
}

TEST(PlanCli, DefaultNamesAreClrendersOwn) {
    TempFolder folder;
    folder.write("anim.json", kAnimation);
    const json selection = plan_of("anim.json --frames 1-2", folder);
    EXPECT_EQ(selection["frame_pattern"], nullptr);
    EXPECT_EQ(paths_of(selection["images"]), (std::vector<std::string>{"anim_0001.png", "anim_0002.png"}));
    EXPECT_EQ(selection["video"], nullptr);
    const json whole = plan_of("anim.json", folder);
    EXPECT_EQ(whole["images"], json::array());
    EXPECT_EQ(whole["video"], "anim.mp4");
    EXPECT_EQ(whole["writes"], json({"anim.mp4"}));
}

TEST(PlanCli, AStillSplitsByRowsOfTheRenderedRectangle) {
    TempFolder folder;
    folder.write("still.json", kStill);
    const json plan = plan_of("still.json --size 40x25 --stats - ", folder);
    EXPECT_EQ(plan["still"], true);
    EXPECT_EQ(plan["frames"], json({0}));
    EXPECT_EQ(paths_of(plan["images"]), std::vector<std::string>{"still.png"});
    EXPECT_EQ(plan["stats"], "-");
    EXPECT_EQ(plan["split"], json({{"by", "rows"}, {"x0", 0}, {"x1", 40}, {"y0", 0}, {"y1", 25}}));
    const json crop = plan_of("still.json --crop 3,13,4,9 -o tile.png", folder);
    EXPECT_EQ(crop["width"], 10);
    EXPECT_EQ(crop["height"], 5);
    EXPECT_EQ(crop["frame_width"], 30);
    EXPECT_EQ(crop["split"], json({{"by", "rows"}, {"x0", 3}, {"x1", 13}, {"y0", 4}, {"y1", 9}}));
    const json join = plan_of("still.json --join a.png --join b.png -o j.png", folder);
    EXPECT_EQ(join["split"], json({{"by", "none"}}));
    EXPECT_EQ(join["reads_back"], json({"a.png", "b.png"}));
    EXPECT_EQ(join["device"], nullptr);
}

// With --resume the plan says which frames are finished (read back, not written), as the
// render then finds them: a frame of this very render (the reference's, as this run's).
// A farm without a shared folder copies each node its inputs: the plan names every file the
// render reads, each once, relative to the working folder: the scene, its images, its OBJ
// files (a `surfaces` mesh too) and the .mtl files they name.
TEST(PlanCli, ThePlanNamesEveryFileTheRenderReads) {
    TempFolder folder;
    fs::create_directories(folder.file("s/m"));
    folder.write("s/m/cube.mtl", "newmtl red\nKd 1 0 0\n");
    folder.write("s/m/cube.obj", "mtllib cube.mtl\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    folder.write("s/sign.ppm", std::string("P6\n1 1\n255\n") + std::string(3, '\x80'));
    folder.write("s/scene.json", R"({
  "eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60, "width": 30, "height": 20,
  "obj": [{"filename": "m/cube.obj"}, {"filename": "m/cube.obj", "position": [1, 0, 0]}],
  "surfaces": [{"type": "mesh", "filename": "m/cube.obj", "ambient": [0, 1, 0]}],
  "billboards": [{"filename": "sign.ppm",
                  "UpperLeft": [-2, 2, -1], "LowerLeft": [-2, 1, -1], "UpperRight": [-1, 2, -1]}]
})");
    const json plan = plan_of("s/scene.json", folder);
    EXPECT_EQ(plan["reads"], json({"s/scene.json", "s/sign.ppm", "s/m/cube.obj", "s/m/cube.mtl"}));
    const json join = plan_of("s/scene.json --join t.png", folder);
    EXPECT_EQ(join["reads"], plan["reads"]);  // the tiles are in reads_back
}

// With --placeholders an OBJ refused for a bad line was read all the same, and so were the
// .mtl files it names (for the textures they name, which no output may replace): the plan
// lists them, as it lists the files of a model that loads. A missing OBJ was not read.
TEST(PlanCli, ThePlanNamesTheFilesReadOfAMeshThatAPlaceholderStandsInFor) {
    TempFolder folder;
    folder.write("lib.mtl", "newmtl red\nKd 1 0 0\nmap_Kd wood.png\n");
    folder.write("bad.obj", "mtllib lib.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
    folder.write("scene.json", R"({
  "eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60, "width": 30, "height": 20,
  "obj": [{"filename": "bad.obj"}, {"filename": "gone.obj"}]
})");
    const auto result = run_clrender("scene.json --placeholders --plan", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    // The placeholders' warnings come first (standard error, while the scene loads), a line each.
    const std::size_t plan_start = result.output.find("\n{");
    ASSERT_NE(plan_start, std::string::npos) << result.output;
    const json plan = json::parse(result.output.substr(plan_start + 1));
    EXPECT_EQ(plan["reads"], json({"scene.json", "bad.obj", "lib.mtl"}));
}

// A file named two ways is one file, listed once: an OBJ placed as "m.obj" and "./m.obj", and
// a .mtl it names as "red.mtl" and "./red.mtl" (listed twice before).
TEST(PlanCli, AFileNamedTwoWaysIsListedOnce) {
    TempFolder folder;
    folder.write("red.mtl", "newmtl red\nKd 1 0 0\n");
    folder.write("m.obj", "mtllib red.mtl ./red.mtl\nmtllib .//red.mtl\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                          "f 1 2 3\n");
    folder.write("scene.json", R"({
  "eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60, "width": 30, "height": 20,
  "obj": [{"filename": "m.obj"}, {"filename": "./m.obj", "position": [1, 0, 0]}]
})");
    EXPECT_EQ(plan_of("scene.json", folder)["reads"], json({"scene.json", "m.obj", "red.mtl"}));
}

TEST(PlanCli, ResumeMarksTheFinishedFrames) {
    TempFolder folder;
    folder.write("anim.json", kAnimation);
    ASSERT_EQ(run_clrender("anim.json --frames 1 -o 'f_%04d.png' -q --reference", folder.path()).exit_code, 0);
    const json plan = plan_of("anim.json --frames 0-2 -o 'f_%04d.png' --resume --reference", folder);
    EXPECT_EQ(plan["writes"], json({"f_0000.png", "f_0002.png"}));
    EXPECT_EQ(plan["reads_back"], json({"f_0001.png"}));
    EXPECT_EQ(plan["images"][1]["written"], false);
}

TEST(PlanCli, TheDeviceIsTheSelectorAsGivenAndNoPlatformIsOpened) {
    TempFolder folder;
    folder.write("still.json", kStill);
    fs::create_directories(folder.file("icds"));
    fs::create_directories(folder.file("ld"));
    folder.write("icds/probe.icd", "libclrender_icd_probe.so\n");
    // The dynamic linker's log, one file per process, says whether the probe was looked for.
    const std::string environment =
        "OCL_ICD_VENDORS=" + folder.file("icds") + " LD_DEBUG=libs LD_DEBUG_OUTPUT=" + folder.file("ld/log");
    const auto linker_log_names_the_probe = [&folder] {
        bool found = false;
        for (const auto& entry : fs::directory_iterator(folder.file("ld"))) {
            found = found || testing::read_bytes(entry.path()).find("libclrender_icd_probe.so") != std::string::npos;
            fs::remove(entry.path());
        }
        return found;
    };
    run_clrender("--list-devices", folder.path(), environment);
    ASSERT_TRUE(linker_log_names_the_probe()) << "the probe does not work";
    EXPECT_EQ(plan_of("still.json -d 'no such device'", folder, environment)["device"], "no such device");
    EXPECT_FALSE(linker_log_names_the_probe()) << "--plan opened an OpenCL platform";
    EXPECT_EQ(plan_of("still.json", folder, "CLRENDER_DEVICE=gpu")["device"], "gpu");
    EXPECT_EQ(plan_of("still.json --reference -d 0", folder)["device"], nullptr);
}

// A plan or summary that cannot reach standard output is an output error, not a success.
TEST(PlanCli, AFullStandardOutputIsAnOutputError) {
    TempFolder folder;
    folder.write("still.json", kStill);
    for (const char* mode : {"--plan", "--check"}) {
        EXPECT_EQ(run_clrender(std::string("still.json ") + mode + " >/dev/full", folder.path()).exit_code, 4) << mode;
        EXPECT_EQ(run_clrender(std::string("still.json ") + mode + " >/dev/null", folder.path()).exit_code, 0) << mode;
    }
}

// --list-devices -d: the device a render would pick, or the render's refusal.
TEST(PlanCli, ListDevicesWithASelectorNamesTheDeviceOrRefusesAsARender) {
    TempFolder folder;
    folder.write("still.json", kStill);
    const auto all = run_clrender("--list-devices", folder.path());
    if (all.output.find("[0]") == std::string::npos) GTEST_SKIP() << "no OpenCL device here";
    const auto first = run_clrender("--list-devices -d 0", folder.path());
    EXPECT_EQ(first.exit_code, 0);
    EXPECT_NE(first.output.find("[0] "), std::string::npos) << first.output;
    EXPECT_EQ(first.output.find("[1] "), std::string::npos) << first.output;
    const auto render = run_clrender("still.json -q -d nosuchdevicexyz -o s.png", folder.path());
    ASSERT_EQ(render.exit_code, 3) << render.output;
    const auto listed = run_clrender("--list-devices -d nosuchdevicexyz", folder.path());
    EXPECT_EQ(listed.exit_code, 3);
    EXPECT_EQ(listed.output, render.output);
    // CLRENDER_DEVICE does not narrow the listing: it is the default of renders only.
    EXPECT_EQ(run_clrender("--list-devices", folder.path(), "CLRENDER_DEVICE=nosuchdevicexyz").output, all.output);
}

}  // namespace
}  // namespace clr
