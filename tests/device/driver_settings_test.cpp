// Settings clrender gives the OpenCL drivers: with PoCL, a cold start compiles render_packets'
// work-group function once, generic, and the program binary stored for the next run reuses it.
#include "device/driver_settings.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "support/command.h"
#include "support/opencl_test_device.h"
#include "support/scoped_env.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::run_clrender;
using testing::ScopedEnv;
using testing::TempFolder;

TEST(DriverSettings, SpecialisationIsOffUnlessTheUserChose) {
    ScopedEnv unset("POCL_WORK_GROUP_SPECIALIZATION", nullptr);
    apply_driver_settings();
    ASSERT_NE(std::getenv("POCL_WORK_GROUP_SPECIALIZATION"), nullptr);
    EXPECT_EQ(std::string(std::getenv("POCL_WORK_GROUP_SPECIALIZATION")), "0");

    ScopedEnv chosen("POCL_WORK_GROUP_SPECIALIZATION", "1");
    apply_driver_settings();
    EXPECT_EQ(std::string(std::getenv("POCL_WORK_GROUP_SPECIALIZATION")), "1");
}

TEST(DriverSettings, CacheOffTurnsPoclsKernelCacheOffUnlessTheUserChose) {
    ScopedEnv unset("POCL_KERNEL_CACHE", nullptr);
    {
        ScopedEnv cache("CLRENDER_CACHE_DIR", "/tmp/somewhere");
        apply_driver_settings();
        EXPECT_EQ(std::getenv("POCL_KERNEL_CACHE"), nullptr) << "a cache folder leaves PoCL's cache alone";
    }
    ScopedEnv off("CLRENDER_CACHE_DIR", "off");
    apply_driver_settings();
    ASSERT_NE(std::getenv("POCL_KERNEL_CACHE"), nullptr);
    EXPECT_EQ(std::string(std::getenv("POCL_KERNEL_CACHE")), "0");

    ScopedEnv chosen("POCL_KERNEL_CACHE", "1");
    apply_driver_settings();
    EXPECT_EQ(std::string(std::getenv("POCL_KERNEL_CACHE")), "1");
}

// PoCL's cache entries: a folder per program. (PoCL leaves an empty temporary file there even
// with its cache off: not an entry.)
int kernel_entries(const std::string& pocl_cache) {
    int folders = 0;
    for (const auto& entry : fs::directory_iterator(pocl_cache)) folders += entry.is_directory();
    return folders;
}

// Through the binary: with CLRENDER_CACHE_DIR=off a run leaves no kernel in PoCL's cache folder.
TEST(DriverSettings, CacheOffLeavesPoclsCacheFolderEmpty) {
    if (testing::test_device().entry().platform_name.find("Portable Computing Language") == std::string::npos)
        GTEST_SKIP() << "the test device is not PoCL";
    TempFolder folder;
    folder.write("scene.json", R"({"eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
      "width": 40, "height": 30, "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0, 0]}]})");
    fs::create_directory(folder.file("pocl"));
    const std::string pocl = "POCL_CACHE_DIR='" + folder.file("pocl") + "'";
    auto off = run_clrender("-q scene.json -o out.png", folder.path(),
                            "env -u POCL_KERNEL_CACHE " + pocl + " CLRENDER_CACHE_DIR=off");
    ASSERT_EQ(off.exit_code, 0) << off.output;
    EXPECT_EQ(kernel_entries(folder.file("pocl")), 0) << "PoCL cached kernels with the cache off";

    // The check above can fail: the same run with a cache folder fills PoCL's.
    fs::create_directory(folder.file("clrender"));
    auto on = run_clrender("-q scene.json -o out.png", folder.path(),
                           "env -u POCL_KERNEL_CACHE " + pocl + " CLRENDER_CACHE_DIR='" + folder.file("clrender") + "'");
    ASSERT_EQ(on.exit_code, 0) << on.output;
    EXPECT_GT(kernel_entries(folder.file("pocl")), 0);
}

// PoCL keeps each work-group function it compiles in its cache folder, one folder per variant
// (local size, and for specialised ones global offset and grid size): a cold run that also
// stores its program binary must leave exactly one, the generic one.
TEST(DriverSettings, AColdRunCompilesOneWorkGroupFunction) {
    if (testing::test_device().entry().platform_name.find("Portable Computing Language") == std::string::npos)
        GTEST_SKIP() << "the test device is not PoCL";
    TempFolder folder;
    folder.write("scene.json", R"({"eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
      "width": 40, "height": 30, "DefaultColor": [0.1, 0.1, 0.1],
      "spheres": [{"type": "sphere", "center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0, 0]}]})");
    fs::create_directory(folder.file("pocl"));
    fs::create_directory(folder.file("clrender"));
    // Not inherited from this process, where the setting is made already: clrender makes it.
    const std::string environment = "env -u POCL_WORK_GROUP_SPECIALIZATION POCL_CACHE_DIR='" + folder.file("pocl") +
                                    "' CLRENDER_CACHE_DIR='" + folder.file("clrender") + "'";
    auto result = run_clrender("-q scene.json -o out.png", folder.path(), environment);
    ASSERT_EQ(result.exit_code, 0) << result.output;

    std::vector<std::string> variants;
    for (const auto& entry : fs::recursive_directory_iterator(folder.file("pocl")))
        if (entry.is_directory() && entry.path().parent_path().filename() == "render_packets")
            variants.push_back(entry.path().filename().string());
    ASSERT_EQ(variants.size(), 1u) << "one work-group function of render_packets, not " << variants.size();
    EXPECT_EQ(variants.front(), "0-0-0") << "the generic one, which the program binary holds";
}

}  // namespace
}  // namespace clr
