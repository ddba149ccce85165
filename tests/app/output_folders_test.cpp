// Outputs in folders that do not exist yet: made for images, frame patterns, videos and the
// --stats report, with the umask's permissions, only once the run's checks have passed; and
// the recipes that name new folders (clrender's own frame-pattern hint, docs/farm.md's
// GNU parallel recipe) work as written in a fresh folder.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>

#include "support/command.h"
#include "support/small_disk.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::have_program;
using testing::read_bytes;
using testing::run_clrender;
using testing::TempFolder;

const char* kStill = R"({"eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
  "width": 16, "height": 12, "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0.3, 0.2]}]})";

// Three frames: two keys, two frames per segment.
const char* kAnimation = R"({"eyeLocations": [[-3, 1, 8], [3, 2, 7]], "lookat": [0, 0, 0], "up": [0, 1, 0],
  "fov_angle": 55, "width": 16, "height": 12, "clrender": {"frames_per_segment": 2},
  "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0.3, 0.2]}]})";

mode_t permissions_of(const std::string& path) {
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0) return 0;
    return info.st_mode & 07777;
}

TEST(OutputFolders, AreMadeForTheImageAndTheStatsReport) {
    TempFolder folder;
    folder.write("scene.json", kStill);
    auto result = run_clrender("scene.json -q -o renders/stills/out.png --stats logs/run.json", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_TRUE(fs::is_regular_file(folder.file("renders/stills/out.png")));
    EXPECT_TRUE(fs::is_regular_file(folder.file("logs/run.json")));
}

TEST(OutputFolders, AreMadeForFramesAndTheVideo) {
    if (!have_program("ffmpeg") || !have_program("ffprobe")) GTEST_SKIP() << "ffmpeg is not installed";
    TempFolder folder;
    folder.write("anim.json", kAnimation);
    auto result = run_clrender("anim.json -q -o 'frames/f_%04d.png' --video videos/2026/anim.mp4", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    for (const char* name : {"frames/f_0000.png", "frames/f_0001.png", "frames/f_0002.png", "videos/2026/anim.mp4"})
        EXPECT_TRUE(fs::is_regular_file(folder.file(name))) << name;
}

TEST(OutputFolders, GetTheUmasksPermissions) {
    TempFolder folder;
    folder.write("scene.json", kStill);
    auto result = run_clrender("scene.json -q -o a/b/out.png", folder.path(), "umask 027;");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_EQ(permissions_of(folder.file("a")), 0750u);
    EXPECT_EQ(permissions_of(folder.file("a/b")), 0750u);
    result = run_clrender("scene.json -q -o c/out.png", folder.path(), "umask 002;");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_EQ(permissions_of(folder.file("c")), 0775u);
}

// The device is chosen after the outputs are planned: a run it refuses must not leave the
// folders it would have written to.
TEST(OutputFolders, ARunRefusedBeforeRenderingMakesNone) {
    TempFolder folder;
    folder.write("scene.json", kStill);
    auto result = run_clrender("scene.json -q -o new/out.png --stats newer/run.json -d no-such-device", folder.path());
    EXPECT_EQ(result.exit_code, 3) << result.output;
    EXPECT_EQ(folder.entry_count(), 1) << "only scene.json";
}

TEST(OutputFolders, ARunRefusedForAnotherOutputMakesNone) {
    TempFolder folder;
    folder.write("scene.json", kStill);
    auto result = run_clrender("scene.json -q -o new/out.png --stats scene.json/run.json", folder.path());
    EXPECT_EQ(result.exit_code, 4) << result.output;
    EXPECT_NE(result.output.find("scene.json/run.json"), std::string::npos) << result.output;
    EXPECT_EQ(folder.entry_count(), 1) << "only scene.json";
}

TEST(OutputFolders, AFolderOnAReadOnlyDiskIsRefusedBeforeRendering) {
    if (!testing::can_mount_small_disks()) GTEST_SKIP() << "cannot mount a tmpfs (needs root or unprivileged user namespaces)";
    TempFolder folder;
    folder.write("scene.json", kStill);
    const int status = testing::run_in_mount_namespace(
        folder.path(), "mkdir ro; mount -t tmpfs -o ro,size=64k tmpfs ro; set +e; "
                       "\"$CLRENDER\" scene.json -q -o ro/new/out.png > out.txt 2>&1; code=$?; set -e; "
                       "ls -A ro > listing.txt; exit $code");
    EXPECT_EQ(status, 4) << read_bytes(folder.file("out.txt"));
    EXPECT_NE(read_bytes(folder.file("out.txt")).find("ro/new/out.png: cannot create the folder 'ro/new': Read-only file system"),
              std::string::npos)
        << read_bytes(folder.file("out.txt"));
    EXPECT_EQ(read_bytes(folder.file("listing.txt")), "") << "nothing may be made on the read-only disk";
}

// The usage error for a plain -o with several frames suggests a pattern in a folder: that
// suggestion must work as given.
TEST(OutputFolders, TheFramePatternHintWorksAsWritten) {
    TempFolder folder;
    folder.write("anim.json", kAnimation);
    auto refused = run_clrender("anim.json -o plain.png", folder.path());
    ASSERT_EQ(refused.exit_code, 1) << refused.output;
    std::smatch hint;
    ASSERT_TRUE(std::regex_search(refused.output, hint, std::regex(R"(such as (\S+))"))) << refused.output;
    EXPECT_EQ(hint[1].str(), "frames/anim_%04d.png");
    auto result = run_clrender("anim.json -q -o '" + hint[1].str() + "'", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    for (const char* name : {"frames/anim_0000.png", "frames/anim_0001.png", "frames/anim_0002.png"})
        EXPECT_TRUE(fs::is_regular_file(folder.file(name))) << name;
}

// The shell block of docs/farm.md's "Several processes without Slurm: GNU parallel", run as
// written (clrender on PATH, the scene as scene.json) in a folder without out/: the
// parallel jobs all make out/ at once.
std::string documented_parallel_recipe() {
    const std::string doc = read_bytes(std::string(CLRENDER_SOURCE_DIR) + "/docs/farm.md");
    const std::size_t section = doc.find("## Several processes without Slurm: GNU parallel");
    const std::size_t start = doc.find("```sh\n", section);
    const std::size_t end = doc.find("```", start + 6);
    if (section == std::string::npos || start == std::string::npos || end == std::string::npos) return "";
    return doc.substr(start + 6, end - start - 6);
}

TEST(OutputFolders, TheDocumentedParallelRecipeWorksInAFreshFolder) {
    if (!have_program("parallel") || !have_program("ffmpeg")) GTEST_SKIP() << "GNU parallel or ffmpeg is not installed";
    const std::string recipe = documented_parallel_recipe();
    ASSERT_NE(recipe.find("out/frame_%04d.png"), std::string::npos) << recipe;
    TempFolder folder;
    folder.write("scene.json", kAnimation);
    folder.write("recipe.sh", "set -e\n" + recipe);
    fs::create_directories(folder.file("bin"));
    fs::create_symlink(CLRENDER_BINARY, folder.file("bin/clrender"));
    const std::string command = "cd '" + folder.path() + "' && PATH=\"$PWD/bin:$PATH\" bash recipe.sh > recipe.log 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << read_bytes(folder.file("recipe.log"));
    for (const char* name : {"out/frame_0000.png", "out/frame_0001.png", "out/frame_0002.png", "out/video.mp4"})
        EXPECT_TRUE(fs::is_regular_file(folder.file(name))) << name;
}

}  // namespace
}  // namespace clr
