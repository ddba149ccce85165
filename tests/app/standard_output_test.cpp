// Whatever clrender prints on standard output must arrive: a full disk behind it (/dev/full) is
// an output error, exit 4 with one error line, never exit 0 with the output lost.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <string>

#include "support/command.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

using testing::read_bytes;
using testing::TempFolder;

const char* kScene = R"({
  "eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
  "width": 40, "height": 30, "DefaultColor": [0.1, 0.1, 0.1],
  "spheres": [{"type": "sphere", "center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0, 0]}]
})";

struct Outcome {
    int code = -1;
    std::string stderr_text;
};

Outcome run_into_full_disk(const TempFolder& folder, const std::string& arguments) {
    const std::string command = "cd '" + folder.path() + "' && '" + CLRENDER_BINARY + "' " + arguments +
                                " >/dev/full 2>stderr.txt";
    const int status = std::system(command.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_bytes(folder.file("stderr.txt"))};
}

TEST(StandardOutput, AFullDiskBehindStandardOutputIsAnOutputError) {
    TempFolder folder;
    folder.write("scene.json", kScene);
    for (const char* arguments : {"scene.json --check", "--list-devices", "scene.json --frame-count", "--help",
                                  "--version", "scene.json -q --reference -o out.png --stats -",
                                  "scene.json --reference --explain-pixel 3,4"}) {
        const Outcome outcome = run_into_full_disk(folder, arguments);
        EXPECT_EQ(outcome.code, 4) << arguments << ": " << outcome.stderr_text;
        EXPECT_EQ(outcome.stderr_text.rfind("clrender: error: ", 0), 0u) << arguments << ": " << outcome.stderr_text;
        EXPECT_NE(outcome.stderr_text.find("standard output"), std::string::npos) << arguments << ": " << outcome.stderr_text;
        EXPECT_NE(outcome.stderr_text.find("\n"), std::string::npos);
        EXPECT_EQ(outcome.stderr_text.find("\n"), outcome.stderr_text.size() - 1) << "one line: " << outcome.stderr_text;
    }
}

// The same commands with standard output writable succeed: the check is of the output, not of
// the commands.
TEST(StandardOutput, TheSameCommandsSucceedIntoAFile) {
    TempFolder folder;
    folder.write("scene.json", kScene);
    for (const char* arguments : {"scene.json --check", "--list-devices", "scene.json --frame-count", "--help",
                                  "--version", "scene.json --reference --explain-pixel 3,4"}) {
        const std::string command = "cd '" + folder.path() + "' && '" + CLRENDER_BINARY + "' " + arguments +
                                    " >stdout.txt 2>stderr.txt";
        const int status = std::system(command.c_str());
        EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << arguments << ": " << read_bytes(folder.file("stderr.txt"));
        EXPECT_FALSE(read_bytes(folder.file("stdout.txt")).empty()) << arguments;
    }
}

}  // namespace
}  // namespace clr
