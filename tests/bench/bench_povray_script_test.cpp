// scripts/bench_povray.sh's refusals, which come before it installs or builds anything: without
// the course scenes beside the repository it exits 77 (skipped, in the automake convention)
// with a message saying what to pass instead, and a bad option is a usage error.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/shell.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::CommandResult;
using testing::run_shell;
using testing::shell_quoted;
using testing::TempFolder;

// The script, copied into `folder`/repo/scripts, where ../shared does not exist.
std::string script_without_course_scenes(const TempFolder& folder) {
    fs::create_directories(folder.file("repo/scripts"));
    const std::string script = folder.file("repo/scripts/bench_povray.sh");
    fs::copy_file(std::string(CLRENDER_SOURCE_DIR) + "/scripts/bench_povray.sh", script);
    return script;
}

TEST(BenchPovrayScript, WithoutCourseScenesExits77AndBuildsNothing) {
    TempFolder folder;
    const std::string script = script_without_course_scenes(folder);
    CommandResult result = run_shell("bash " + shell_quoted(script));
    EXPECT_EQ(result.exit_code, 77) << result.output;
    EXPECT_NE(result.output.find("the course scenes are not here"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("shared/course-scenes/spring2023-a03/testScene_grads.json is missing"),
              std::string::npos)
        << result.output;
    EXPECT_NE(result.output.find("give a scene path"), std::string::npos) << result.output;
    EXPECT_FALSE(fs::exists(folder.file("repo/build-bench")));
}

TEST(BenchPovrayScript, BadOptionsAreUsageErrors) {
    TempFolder folder;
    const std::string script = script_without_course_scenes(folder);
    for (const char* options : {"--size 1920", "--size 0x10", "--repeat 0", "--repeat x", "--frobnicate"}) {
        CommandResult result = run_shell("bash " + shell_quoted(script) + " " + options);
        EXPECT_EQ(result.exit_code, 1) << options << ": " << result.output;
        EXPECT_NE(result.output.find("bench_povray: "), std::string::npos) << options << ": " << result.output;
    }
    CommandResult missing = run_shell("bash " + shell_quoted(script) + " " + shell_quoted(folder.file("none.json")));
    EXPECT_EQ(missing.exit_code, 2) << missing.output;
    EXPECT_NE(missing.output.find("no scene file"), std::string::npos) << missing.output;
}

}  // namespace
}  // namespace clr
