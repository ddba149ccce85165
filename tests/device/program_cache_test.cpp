// The program cache: binaries kept across runs under a folder from the environment, used
// only for exactly the same build, and never an error when an entry is bad.
#include "device/program_cache.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "device/device_context.h"
#include "device/kernel_sources.h"
#include "render/feature_set.h"
#include "support/opencl_test_device.h"
#include "support/scoped_env.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::TempFolder;

using testing::ScopedEnv;

TEST(ProgramCache, FolderComesFromTheEnvironment) {
    {
        ScopedEnv dir("CLRENDER_CACHE_DIR", "/some/where");
        EXPECT_EQ(ProgramCache::from_environment().folder(), "/some/where");
    }
    for (const char* off : {"off", ""}) {
        ScopedEnv dir("CLRENDER_CACHE_DIR", off);
        EXPECT_FALSE(ProgramCache::from_environment().enabled()) << "'" << off << "'";
    }
    ScopedEnv dir("CLRENDER_CACHE_DIR", nullptr);
    {
        ScopedEnv xdg("XDG_CACHE_HOME", "/xdg");
        EXPECT_EQ(ProgramCache::from_environment().folder(), "/xdg/clrender");
    }
    ScopedEnv xdg("XDG_CACHE_HOME", nullptr);
    ScopedEnv home("HOME", "/home/someone");
    EXPECT_EQ(ProgramCache::from_environment().folder(), "/home/someone/.cache/clrender");
}

TEST(ProgramCache, AnEntryServesOnlyItsOwnKeyAndABadOneIsAMiss) {
    TempFolder folder;
    ProgramCache cache(folder.file("nested/cache"));  // created on the first store
    const std::string key = "device\\0options\\0source";
    EXPECT_FALSE(cache.load(key));
    cache.store(key, {1, 2, 3, 4});
    ASSERT_TRUE(cache.load(key));
    EXPECT_EQ(*cache.load(key), (std::vector<unsigned char>{1, 2, 3, 4}));
    EXPECT_FALSE(cache.load(key + " "));
    EXPECT_EQ(std::distance(fs::directory_iterator(folder.file("nested/cache")), fs::directory_iterator()), 1)
        << "no temporary file left behind";

    const std::string path = cache.path(key);
    const std::string whole = testing::read_bytes(path);
    for (std::size_t cut : {std::size_t{0}, std::size_t{5}, whole.size() / 2, whole.size() - 1}) {
        std::ofstream(path, std::ios::binary | std::ios::trunc).write(whole.data(), static_cast<std::streamsize>(cut));
        EXPECT_FALSE(cache.load(key)) << "truncated to " << cut << " bytes";
    }
    std::ofstream(path, std::ios::binary | std::ios::trunc) << whole << "extra";
    EXPECT_FALSE(cache.load(key)) << "trailing bytes";
    fs::remove(path);
    fs::create_directory(path);  // unreadable as a file
    EXPECT_FALSE(cache.load(key));
    cache.store(key, {5});  // cannot replace a folder: quietly nothing
    EXPECT_FALSE(cache.load(key));
}

TEST(ProgramCache, ASecondBuildComesFromTheCacheAndACorruptEntryIsRebuilt) {
    TempFolder folder;
    ScopedEnv dir("CLRENDER_CACHE_DIR", folder.path().c_str());
    const std::string source = assemble_program_source("");
    FeatureSet features;
    features.spheres = true;
    const std::string options = features.build_options();
    const DeviceEntry& entry = testing::test_device().entry();

    const std::string path = ProgramCache(folder.path()).path(ProgramCache::key(entry.device, source, options));
    {
        DeviceContext first(entry);
        first.build_program(source, options);
        EXPECT_EQ(first.cache_hits(), 0);
        EXPECT_FALSE(fs::exists(path)) << "stored on request, after the frames";
        first.store_built_programs();
    }
    ASSERT_TRUE(fs::exists(path));

    DeviceContext second(entry);
    cl::Program cached = second.build_program(source, options);
    EXPECT_EQ(second.cache_hits(), 1);
    EXPECT_NO_THROW(cl::Kernel(cached, "render_packets"));

    DeviceContext other(entry);
    other.build_program(source, options + " -DCLR_UNUSED=1");
    EXPECT_EQ(other.cache_hits(), 0) << "other options, another entry";

    const std::string whole = testing::read_bytes(path);
    std::string corrupt = whole;
    for (std::size_t i = corrupt.size() - 64; i < corrupt.size(); ++i) corrupt[i] = static_cast<char>(~corrupt[i]);
    std::ofstream(path, std::ios::binary | std::ios::trunc) << corrupt;
    DeviceContext third(entry);
    cl::Program rebuilt = third.build_program(source, options);
    EXPECT_NO_THROW(cl::Kernel(rebuilt, "render_packets"));
}

}  // namespace
}  // namespace clr
