// clrender_build_program_store as the build runs it: it fills the store for the default device,
// and where there is no OpenCL device it leaves the store empty, says so and still succeeds, so
// that a build never fails for want of a device.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/shell.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::run_shell;
using testing::shell_quoted;
using testing::TempFolder;

const std::string kBuilder = std::string(CLRENDER_BUILD_DIR) + "/clrender_build_program_store";

TEST(BuildProgramStore, WithoutADeviceLeavesAnEmptyStoreAndSucceeds) {
    TempFolder folder;
    const std::string store = folder.file("programs");
    fs::create_directories(store);
    const std::string stale = store + "/" + std::string(64, 'a') + ".clbin";
    folder.write("programs/" + std::string(64, 'a') + ".clbin", "an entry of another build");
    folder.write("programs/README", "not ours");
    // No ICD file: no OpenCL platform at all.
    const auto result = run_shell("OCL_ICD_VENDORS=" + shell_quoted(folder.path()) + " " + shell_quoted(kBuilder) +
                                  " " + shell_quoted(store) + " 2>&1");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("no OpenCL device"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("is empty"), std::string::npos) << result.output;
    EXPECT_FALSE(fs::exists(stale));
    EXPECT_TRUE(fs::exists(store + "/README")) << "only entries of ours are removed";
}

TEST(BuildProgramStore, RefusesAWrongCommandLine) {
    for (const char* arguments : {"", "a b", "a --double", "''"})
        EXPECT_EQ(run_shell(shell_quoted(kBuilder) + " " + arguments + " 2>/dev/null").exit_code, 1) << arguments;
}

}  // namespace
}  // namespace clr
