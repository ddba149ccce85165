// The program cache: binaries kept across runs under a folder from the environment, used
// only for exactly the same build, and never an error when an entry is bad.
#include "device/program_cache.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "core/sha256.h"
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
        EXPECT_EQ(ProgramCache::from_environment().folder(), "/some/where/programs");
    }
    for (const char* off : {"off", ""}) {
        ScopedEnv dir("CLRENDER_CACHE_DIR", off);
        EXPECT_FALSE(ProgramCache::from_environment().enabled()) << "'" << off << "'";
    }
    ScopedEnv dir("CLRENDER_CACHE_DIR", nullptr);
    {
        ScopedEnv xdg("XDG_CACHE_HOME", "/xdg");
        EXPECT_EQ(ProgramCache::from_environment().folder(), "/xdg/clrender/programs");
    }
    ScopedEnv xdg("XDG_CACHE_HOME", nullptr);
    ScopedEnv home("HOME", "/home/someone");
    EXPECT_EQ(ProgramCache::from_environment().folder(), "/home/someone/.cache/clrender/programs");
}

ProgramCache::Key key_of(const std::string& text) { return sha256(text.data(), text.size()); }

int files_in(const std::string& folder) {
    return static_cast<int>(std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
}

TEST(ProgramCache, AnEntryServesOnlyItsOwnKeyAndABadOneIsAMiss) {
    TempFolder folder;
    ProgramCache cache(folder.file("nested/cache"));  // created on the first store
    const ProgramCache::Key key = key_of("device options source");
    EXPECT_FALSE(cache.load(key));
    cache.store(key, {1, 2, 3, 4});
    ASSERT_TRUE(cache.load(key));
    EXPECT_EQ(*cache.load(key), (std::vector<unsigned char>{1, 2, 3, 4}));
    EXPECT_FALSE(cache.load(key_of("device options source ")));
    EXPECT_EQ(cache.path(key), folder.file("nested/cache/programs/" + to_hex(key) + ".clbin"));
    EXPECT_EQ(files_in(cache.folder()), 1) << "no temporary file left behind";

    const std::string path = cache.path(key);
    const std::string whole = testing::read_bytes(path);
    for (std::size_t cut : {std::size_t{0}, std::size_t{5}, std::size_t{128}, whole.size() / 2, whole.size() - 1}) {
        std::ofstream(path, std::ios::binary | std::ios::trunc).write(whole.data(), static_cast<std::streamsize>(cut));
        EXPECT_FALSE(cache.load(key)) << "truncated to " << cut << " bytes";
    }
    for (std::size_t at = 8; at < whole.size(); ++at) {  // every byte after the magic
        std::string damaged = whole;
        damaged[at] ^= 0x10;
        std::ofstream(path, std::ios::binary | std::ios::trunc) << damaged;
        EXPECT_FALSE(cache.load(key)) << "byte " << at << " damaged";
        EXPECT_FALSE(fs::exists(path)) << "a damaged entry of ours is removed";
    }
    cache.store(key, {1, 2, 3, 4});
    fs::copy_file(path, cache.path(key_of("other")));  // a whole entry under another key's name
    EXPECT_FALSE(cache.load(key_of("other")));
    std::ofstream(path, std::ios::binary | std::ios::trunc) << whole << "extra";
    EXPECT_FALSE(cache.load(key)) << "trailing bytes";
    fs::remove(path);
    fs::create_directory(path);  // unreadable as a file
    EXPECT_FALSE(cache.load(key));
    cache.store(key, {5});  // cannot replace a folder: quietly nothing
    EXPECT_FALSE(cache.load(key));
    EXPECT_TRUE(fs::is_directory(path)) << "not ours: left alone";
}

TEST(ProgramCache, EvictionKeepsTheSizeLimitAndTouchesOnlyItsOwnFiles) {
    TempFolder folder;
    const std::vector<unsigned char> binary(1000, 7);
    ProgramCache cache(folder.path(), 2500);  // room for two entries of 128 + 1000 bytes
    cache.store(key_of("a"), binary);
    cache.store(key_of("b"), binary);
    fs::last_write_time(cache.path(key_of("a")), fs::file_time_type::clock::now() - std::chrono::hours(2));
    fs::last_write_time(cache.path(key_of("b")), fs::file_time_type::clock::now() - std::chrono::hours(1));
    const std::string foreign = folder.write("programs/" + to_hex(key_of("x")) + ".clbin", std::string(5000, 'x'));
    const std::string old_layout = folder.write("0123456789abcdef.bin", std::string(5000, 'x'));  // top of the folder
    fs::last_write_time(foreign, fs::file_time_type::clock::now() - std::chrono::hours(5));
    cache.store(key_of("c"), binary);
    EXPECT_FALSE(cache.load(key_of("a")));
    EXPECT_TRUE(cache.load(key_of("b")));
    EXPECT_TRUE(cache.load(key_of("c")));
    EXPECT_EQ(testing::read_bytes(foreign), std::string(5000, 'x'));
    EXPECT_EQ(testing::read_bytes(old_layout), std::string(5000, 'x'));
}

TEST(ProgramCache, ABorrowedEntryIsFoundAgainOnlyOnceGivenBack) {
    TempFolder folder;
    ProgramCache cache(folder.path());
    const std::vector<unsigned char> binary = {'p', 'o', 'c', 'l', 'b', 'i', 'n', 0, 1, 2};
    cache.store(key_of("a"), binary);
    std::string aside;
    ASSERT_TRUE(cache.borrow(key_of("a"), std::string("poclbin", 8), aside));
    EXPECT_FALSE(cache.load(key_of("a"))) << "held aside while the driver works on it";
    cache.give_back(key_of("a"), aside);
    EXPECT_TRUE(cache.load(key_of("a")));

    // A run that dies in the driver never gives it back: it is not found again, and once stale
    // it is removed.
    ASSERT_TRUE(cache.borrow(key_of("a"), std::string("poclbin", 8), aside));
    EXPECT_FALSE(cache.load(key_of("a")));
    fs::last_write_time(aside, fs::file_time_type::clock::now() - std::chrono::hours(1));
    cache.store(key_of("b"), binary);
    EXPECT_FALSE(fs::exists(aside));

    // Not the driver's kind of binary: refused before the driver sees it, and removed.
    cache.store(key_of("c"), {1, 2, 3, 4, 5, 6, 7, 8, 9});
    EXPECT_FALSE(cache.borrow(key_of("c"), std::string("poclbin", 8), aside));
    EXPECT_FALSE(cache.load(key_of("c")));
    EXPECT_EQ(files_in(cache.folder()), 1) << "only b";
}

TEST(ProgramCache, ASecondBuildComesFromTheCacheAndACorruptEntryIsRebuilt) {
    TempFolder folder;
    ScopedEnv dir("CLRENDER_CACHE_DIR", folder.path().c_str());
    const std::string source = assemble_program_source(kRenderTilesProgram.entry);
    FeatureSet features;
    features.spheres = true;
    const std::string options = features.build_options();
    const DeviceEntry& entry = testing::test_device().entry();

    const ProgramCache cache(folder.path());
    const std::string path = cache.path(ProgramCache::key(entry.device, source, options));
    {
        DeviceContext first(entry);
        first.build_program(source, options);
        EXPECT_EQ(first.cache_hits(), 0);
        EXPECT_FALSE(fs::exists(path)) << "stored on request, after the frames";
        first.store_built_programs();
    }
    ASSERT_TRUE(fs::exists(path));

    {
        DeviceContext second(entry);
        cl::Program cached = second.build_program(source, options);
        EXPECT_EQ(second.cache_hits(), 1);
        EXPECT_NO_THROW(cl::Kernel(cached, "render_packets"));
    }
    ASSERT_TRUE(fs::exists(path)) << "given back when the context ends";

    DeviceContext other(entry);
    other.build_program(source, options + " -DCLR_UNUSED=1");
    EXPECT_EQ(other.cache_hits(), 0) << "other options, another entry";

    const std::string whole = testing::read_bytes(path);
    std::string corrupt = whole;
    for (std::size_t i = corrupt.size() - 64; i < corrupt.size(); ++i) corrupt[i] = static_cast<char>(~corrupt[i]);
    std::ofstream(path, std::ios::binary | std::ios::trunc) << corrupt;
    {
        DeviceContext third(entry);
        cl::Program rebuilt = third.build_program(source, options);
        EXPECT_EQ(third.cache_hits(), 0);
        EXPECT_NO_THROW(cl::Kernel(rebuilt, "render_packets"));
        EXPECT_FALSE(fs::exists(path)) << "the damaged entry is removed";
        third.store_built_programs();
    }
    EXPECT_EQ(testing::read_bytes(path).size(), whole.size()) << "and replaced";
    DeviceContext fourth(entry);
    fourth.build_program(source, options);
    EXPECT_EQ(fourth.cache_hits(), 1);
}

}  // namespace
}  // namespace clr
