// --resume knows its files (docs/command-line.md, Resuming): a PNG under an output's name is
// finished only when its description is this render's; one of another render, or one that
// cannot be read, is rendered again (the bytes then equal a fresh render's) with one warning;
// a finished file is not touched (same inode, same time); a still, a tile and one frame resume
// too, and a finished one needs no device. PPM files count by existence.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <string>

#include "support/command.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::frame_name;
using testing::read_bytes;
using testing::run_clrender;
using testing::TempFolder;

const std::string kStill = R"({"eye": [0, 1, 8], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 50,
  "width": 40, "height": 30, "SunLocation": [10, 20, 10],
  "spheres": [{"center": [-1, 0, 0], "radius": 1.2, "ambient": [0.9, 0.3, 0.2]},
              {"center": [1.5, 0, -1], "radius": 1, "ambient": [0.2, 0.4, 0.9], "IsMirror": 1}]})";

const std::string kAnimation = R"({"eyeLocations": [[-3, 1, 8], [3, 2, 7]], "lookat": [0, 0, 0], "up": [0, 1, 0],
  "fov_angle": 55, "width": 32, "height": 24, "clrender": {"frames": 4},
  "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0.3, 0.2]}]})";

// What must not change when a finished file is skipped: its inode and modification time.
struct FileStamp {
    ino_t inode = 0;
    long long modified_ns = 0;
    bool operator==(const FileStamp& other) const { return inode == other.inode && modified_ns == other.modified_ns; }
};

FileStamp stamp(const std::string& path) {
    struct stat status {};
    if (::stat(path.c_str(), &status) != 0) return {};
    return {status.st_ino, status.st_mtim.tv_sec * 1000000000LL + status.st_mtim.tv_nsec};
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(ResumeChecks, AFinishedStillIsNotRenderedAndNeedsNoDevice) {
    TempFolder folder;
    folder.write("scene.json", kStill);
    ASSERT_EQ(run_clrender("scene.json -q --spp 4 -o still.png", folder.path()).exit_code, 0);
    const FileStamp before = stamp(folder.file("still.png"));
    auto result = run_clrender("scene.json -q --spp 4 -o still.png --resume -d no-such-device", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_EQ(result.output, "clrender: still.png is finished (--resume); nothing to render\n");
    EXPECT_TRUE(stamp(folder.file("still.png")) == before) << "the finished still was written again";
}

TEST(ResumeChecks, AStillOfAnotherSampleCountIsRenderedAgain) {
    TempFolder folder;
    folder.write("scene.json", kStill);
    ASSERT_EQ(run_clrender("scene.json -q --spp 1 -o still.png", folder.path()).exit_code, 0);
    ASSERT_EQ(run_clrender("scene.json -q --spp 4 -o fresh.png", folder.path()).exit_code, 0);
    auto result = run_clrender("scene.json -q --spp 4 -o still.png --resume", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_EQ(result.output, "clrender: warning: still.png: made by another render (Samples per pixel: 1 in the "
                             "file, 4 in this run); rendering it again\n");
    EXPECT_TRUE(read_bytes(folder.file("still.png")) == read_bytes(folder.file("fresh.png")));
}

TEST(ResumeChecks, AStillOfDoubleKernelsIsRenderedAgainByTheFloatOnes) {
    TempFolder folder;
    folder.write("scene.json", kStill);
    ASSERT_EQ(run_clrender("scene.json -q --precision double -o still.png", folder.path()).exit_code, 0);
    ASSERT_EQ(run_clrender("scene.json -q -o fresh.png", folder.path()).exit_code, 0);
    auto result = run_clrender("scene.json -q -o still.png --resume", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_EQ(result.output, "clrender: warning: still.png: made by another render (Precision: double in the file, "
                             "none in this run); rendering it again\n");
    EXPECT_TRUE(read_bytes(folder.file("still.png")) == read_bytes(folder.file("fresh.png")));
}

// An edit that the other keys do not show (a colour) changes the scene's digest.
TEST(ResumeChecks, AStillOfAnEditedSceneIsRenderedAgain) {
    TempFolder folder;
    std::string edited = kStill;
    edited.replace(edited.find("[0.9, 0.3, 0.2]"), 15, "[0.1, 0.8, 0.2]");
    folder.write("scene.json", kStill);
    ASSERT_EQ(run_clrender("scene.json -q -o still.png", folder.path()).exit_code, 0);
    folder.write("scene.json", edited);
    ASSERT_EQ(run_clrender("scene.json -q -o fresh.png", folder.path()).exit_code, 0);
    auto result = run_clrender("scene.json -q -o still.png --resume", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_TRUE(contains(result.output, "clrender: warning: still.png: made by another render (Scene digest: "))
        << result.output;
    EXPECT_TRUE(read_bytes(folder.file("still.png")) == read_bytes(folder.file("fresh.png")));
}

TEST(ResumeChecks, ATruncatedPngIsRenderedAgain) {
    TempFolder folder;
    folder.write("scene.json", kStill);
    ASSERT_EQ(run_clrender("scene.json -q -o still.png", folder.path()).exit_code, 0);
    const std::string whole = read_bytes(folder.file("still.png"));
    folder.write("still.png", whole.substr(0, whole.size() - 40));  // the text chunks are intact
    auto result = run_clrender("scene.json -q -o still.png --resume", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_TRUE(contains(result.output, "clrender: warning: still.png: cannot be read (truncated"))
        << result.output;
    EXPECT_TRUE(contains(result.output, "; rendering it again\n")) << result.output;
    EXPECT_TRUE(read_bytes(folder.file("still.png")) == whole);
}

// What a requeued farm task runs: a finished tile is left alone; a tile of another crop under
// its name is rendered again.
TEST(ResumeChecks, ATileResumes) {
    TempFolder folder;
    folder.write("scene.json", kStill);
    ASSERT_EQ(run_clrender("scene.json -q --crop 0,40,0,15 -o tile.png", folder.path()).exit_code, 0);
    const FileStamp before = stamp(folder.file("tile.png"));
    auto again = run_clrender("scene.json --crop 0,40,0,15 -o tile.png --resume -q --progress json", folder.path());
    ASSERT_EQ(again.exit_code, 0) << again.output;
    // --progress json: the line is a JSON object like every other line on standard error.
    EXPECT_TRUE(contains(again.output, R"({"level":"info","message":"tile.png is finished (--resume); nothing to render"})"))
        << again.output;
    EXPECT_TRUE(stamp(folder.file("tile.png")) == before);

    ASSERT_EQ(run_clrender("scene.json -q --crop 0,40,15,30 -o fresh.png", folder.path()).exit_code, 0);
    auto other = run_clrender("scene.json --crop 0,40,15,30 -o tile.png --resume -q", folder.path());
    ASSERT_EQ(other.exit_code, 0) << other.output;
    EXPECT_TRUE(contains(other.output, "tile.png: made by another render (Crop: 0,40,0,15 in the file, 0,40,15,30 in "
                                       "this run); rendering it again"))
        << other.output;
    EXPECT_TRUE(read_bytes(folder.file("tile.png")) == read_bytes(folder.file("fresh.png")));
}

TEST(ResumeChecks, OneFrameWithAPlainOutputResumes) {
    TempFolder folder;
    folder.write("anim.json", kAnimation);
    ASSERT_EQ(run_clrender("anim.json -q --frames 2 -o frame.png", folder.path()).exit_code, 0);
    auto same = run_clrender("anim.json -q --frames 2 -o frame.png --resume", folder.path());
    ASSERT_EQ(same.exit_code, 0) << same.output;
    EXPECT_TRUE(contains(same.output, "frame.png is finished (--resume)")) << same.output;
    auto other = run_clrender("anim.json -q --frames 3 -o frame.png --resume", folder.path());
    ASSERT_EQ(other.exit_code, 0) << other.output;
    EXPECT_TRUE(contains(other.output, "(Frame: 2 in the file, 3 in this run)")) << other.output;
}

TEST(ResumeChecks, EachFrameOfAPatternIsChecked) {
    TempFolder folder;
    folder.write("anim.json", kAnimation);
    ASSERT_EQ(run_clrender("anim.json -q --frames 0-2 -o 'f_%04d.png'", folder.path()).exit_code, 0);
    const std::string frame_1 = read_bytes(folder.file(frame_name(1)));
    ASSERT_EQ(run_clrender("anim.json -q --frames 1 --spp 2 -o 'f_%04d.png'", folder.path()).exit_code, 0);
    const FileStamp frame_0 = stamp(folder.file(frame_name(0)));
    auto result = run_clrender("anim.json -q --frames 0-2 -o 'f_%04d.png' --resume --stats stats.json", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_EQ(result.output, "clrender: warning: f_0001.png: made by another render (Samples per pixel: 2 in the "
                             "file, 1 in this run); rendering it again\n");
    EXPECT_TRUE(read_bytes(folder.file(frame_name(1))) == frame_1);
    EXPECT_TRUE(stamp(folder.file(frame_name(0))) == frame_0);
    const std::string stats = read_bytes(folder.file("stats.json"));
    EXPECT_TRUE(contains(stats, "\"index\": 1,")) << stats;
    EXPECT_FALSE(contains(stats, "\"index\": 0,")) << stats;
}

// A resumed run says how many frames it rendered and how many it found finished, never that it
// wrote them all; the video holds them all.
TEST(ResumeChecks, TheSummarySaysWhatWasRenderedAndWhatSkipped) {
    TempFolder folder;
    folder.write("anim.json", kAnimation);
    ASSERT_EQ(run_clrender("anim.json -q -o 'f_%04d.png'", folder.path()).exit_code, 0);
    std::filesystem::remove(folder.file(frame_name(3)));
    auto result = run_clrender("anim.json -o 'f_%04d.png' --resume", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_TRUE(contains(result.output, "clrender: wrote f_%04d.png (1 frame rendered, 3 already finished (--resume))\n"))
        << result.output;
    EXPECT_FALSE(contains(result.output, "(4 frames)")) << result.output;
    EXPECT_TRUE(contains(result.output, "clrender: 1 frame(s), kernel ")) << result.output;
    std::filesystem::remove(folder.file(frame_name(0)));
    std::filesystem::remove(folder.file(frame_name(2)));
    result = run_clrender("anim.json -o 'f_%04d.png' --resume", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_TRUE(contains(result.output, "clrender: wrote f_%04d.png (2 frames rendered, 2 already finished (--resume))\n"))
        << result.output;
    // Nothing skipped: the plain count.
    auto again = run_clrender("anim.json -o 'g_%04d.png' --resume", folder.path());
    ASSERT_EQ(again.exit_code, 0) << again.output;
    EXPECT_TRUE(contains(again.output, "clrender: wrote g_%04d.png (4 frames)\n")) << again.output;
}

TEST(ResumeChecks, AnAlphaRunRendersAnOpaqueImageAgain) {
    TempFolder folder;
    folder.write("scene.json", kStill);
    ASSERT_EQ(run_clrender("scene.json -q -o still.png", folder.path()).exit_code, 0);
    auto result = run_clrender("scene.json -q --alpha -o still.png --resume", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_TRUE(contains(result.output, "(alpha channel: no in the file, yes in this run)")) << result.output;
}

// PPM carries no description: any regular file under the name counts as finished.
TEST(ResumeChecks, APpmCountsByExistence) {
    TempFolder folder;
    folder.write("scene.json", kStill);
    folder.write("still.ppm", "not checked");
    auto result = run_clrender("scene.json -q -o still.ppm --resume", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_TRUE(contains(result.output, "still.ppm is finished (--resume)")) << result.output;
    EXPECT_EQ(read_bytes(folder.file("still.ppm")), "not checked");
}

}  // namespace
}  // namespace clr
