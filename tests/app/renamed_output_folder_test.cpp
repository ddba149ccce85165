// Renaming or removing the output folder while a video renders: clrender's temporary files (the
// video being encoded, the encoder's log, a frame being written) are removed through the folder
// they were made in, wherever it went, and the run ends with an output error or completes,
// never leaving one behind.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/command.h"
#include "support/small_disk.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::TempFolder;

// 1500 small frames: long enough to rename the folder while they encode, however fast the
// encoder (300 had been, until frames and encoding overlapped on 4 x264 threads).
const char* kAnimation = R"({
  "eyeLocations": [[-3, 1, 8], [3, 2, 7]], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 55,
  "width": 64, "height": 48, "clrender": {"frames": 1500},
  "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0.3, 0.2]}],
  "billboards": [{"UpperLeft": [-5, 4, -4], "LowerLeft": [-5, -3, -4], "UpperRight": [5, 4, -4], "ambient": [0.2, 0.6, 0.3]}]
})";

std::vector<std::string> temporary_files_in(const std::string& folder) {
    std::vector<std::string> found;
    std::error_code error;
    for (fs::recursive_directory_iterator it(folder, error), end; !error && it != end; it.increment(error))
        if (it->path().filename().string().rfind(".clrender-", 0) == 0) found.push_back(it->path().string());
    return found;
}

// Starts the render into out/, waits until the encoder's temporary file is there, then runs
// `move` (a shell command on out/) and waits for clrender; returns its exit code.
int render_and_move_the_folder(const TempFolder& folder, const std::string& outputs, const std::string& move) {
    fs::create_directory(folder.file("out"));
    folder.write("move.sh", "cd '" + folder.path() + "'\n'" + CLRENDER_BINARY + "' anim.json -q " + outputs +
                                " 2> stderr.txt &\n"
                                "pid=$!\n"
                                "i=0\n"
                                "while ! ls -A out | grep -q '^\\.clrender-.*\\.log$' && [ $i -lt 3000 ]; do sleep 0.01; i=$((i+1)); done\n"
                                "sleep 0.3\n" +
                                move +
                                "\n"
                                "wait $pid\n"
                                "echo $? > code.txt\n");
    if (std::system(("bash '" + folder.file("move.sh") + "'").c_str()) != 0) return -1;
    return std::stoi(read_bytes(folder.file("code.txt")));
}

class RenamedOutputFolder : public ::testing::Test {
protected:
    void SetUp() override {
        if (!testing::have_program("ffmpeg") || !testing::have_program("ffprobe")) GTEST_SKIP() << "no ffmpeg here";
        folder.write("anim.json", kAnimation);
    }
    TempFolder folder;
};

TEST_F(RenamedOutputFolder, TheVideosTemporaryFilesGoWithTheRenamedFolder) {
    const int code = render_and_move_the_folder(folder, "--video out/anim.mp4", "mv out moved");
    const std::string errors = read_bytes(folder.file("stderr.txt"));
    EXPECT_TRUE(code == 0 || code == 4) << code << ": " << errors;
    EXPECT_EQ(temporary_files_in(folder.file("moved")), std::vector<std::string>{}) << errors;
    EXPECT_FALSE(fs::exists(folder.file("moved/anim.mp4")) && code != 0) << "a failed run left a video";
}

TEST_F(RenamedOutputFolder, FramesAndTheVideoInAFolderRenamedMidRender) {
    const int code = render_and_move_the_folder(folder, "-o 'out/f_%04d.png' --video out/anim.mp4", "mv out moved");
    const std::string errors = read_bytes(folder.file("stderr.txt"));
    EXPECT_EQ(code, 4) << "the next frame's folder is gone: " << errors;
    EXPECT_EQ(temporary_files_in(folder.file("moved")), std::vector<std::string>{}) << errors;
    EXPECT_EQ(temporary_files_in(folder.path()), std::vector<std::string>{}) << errors;
}

TEST_F(RenamedOutputFolder, TheFolderMovedIntoAnotherAndReplaced) {
    fs::create_directory(folder.file("elsewhere"));
    const int code = render_and_move_the_folder(folder, "--video out/anim.mp4", "mv out elsewhere/ && mkdir out");
    const std::string errors = read_bytes(folder.file("stderr.txt"));
    EXPECT_TRUE(code == 0 || code == 4) << code << ": " << errors;
    EXPECT_EQ(temporary_files_in(folder.path()), std::vector<std::string>{}) << errors;
}

}  // namespace
}  // namespace clr
