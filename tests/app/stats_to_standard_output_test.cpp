// --stats -: the JSON report on standard output, progress and messages on standard error, no
// file named "-"; a report that cannot be written is an output error that leaves no image.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <nlohmann/json.hpp>

#include "support/command.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::run_clrender;
using testing::TempFolder;

const char* kStill = R"({"eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
  "width": 16, "height": 12, "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0.3, 0.2]}]})";

// Runs clrender in `folder` with standard output to out.txt and standard error to err.txt
// (or `stdout_target`); returns the exit status.
int run_split(const TempFolder& folder, const std::string& arguments, const std::string& stdout_target = "out.txt") {
    const std::string command = "cd '" + folder.path() + "' && '" + CLRENDER_BINARY + "' " + arguments + " > " +
                                stdout_target + " 2> err.txt";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(StatsToStandardOutput, StandardOutputHoldsOnlyTheReport) {
    TempFolder folder;
    folder.write("scene.json", kStill);
    ASSERT_EQ(run_split(folder, "scene.json --stats -"), 0) << read_bytes(folder.file("err.txt"));
    const nlohmann::json report = nlohmann::json::parse(read_bytes(folder.file("out.txt")));  // throws if not JSON alone
    for (const char* key : {"device", "build_ms", "cache_hits", "stages_ms", "frames"})
        EXPECT_TRUE(report.contains(key)) << key << " in " << report.dump();
    EXPECT_EQ(report["frames"].size(), 1u);
    EXPECT_NE(read_bytes(folder.file("err.txt")).find("clrender: wrote scene.png"), std::string::npos)
        << "messages stay on standard error";
    EXPECT_TRUE(fs::is_regular_file(folder.file("scene.png")));
    EXPECT_FALSE(fs::exists(folder.file("-"))) << "no file named '-'";
}

TEST(StatsToStandardOutput, AFileNamedDashIsWrittenAsDotSlashDash) {
    TempFolder folder;
    folder.write("scene.json", kStill);
    ASSERT_EQ(run_split(folder, "scene.json -q --stats ./-"), 0) << read_bytes(folder.file("err.txt"));
    EXPECT_NO_THROW(nlohmann::json::parse(read_bytes(folder.file("-"))));
    EXPECT_EQ(read_bytes(folder.file("out.txt")), "");
}

TEST(StatsToStandardOutput, AFullStandardOutputIsAnOutputErrorAndLeavesNoImage) {
    if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
    TempFolder folder;
    folder.write("scene.json", kStill);
    folder.write("scene.png", "the earlier image");
    EXPECT_EQ(run_split(folder, "scene.json -q --stats -", "/dev/full"), 4);
    const std::string errors = read_bytes(folder.file("err.txt"));
    EXPECT_EQ(errors, "clrender: error: --stats -: cannot write the report to standard output: No space left on device\n");
    EXPECT_EQ(read_bytes(folder.file("scene.png")), "the earlier image");
    EXPECT_EQ(folder.entry_count(), 3) << "scene.json, scene.png, err.txt";
}

}  // namespace
}  // namespace clr
