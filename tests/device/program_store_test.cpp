// The program store: binaries built ahead of need, found beside the executable or through
// CLRENDER_PROGRAM_STORE, used only for exactly the same build, after the program cache misses;
// never written, evicted or cleaned by a run, and a bad entry is only a miss.
#include "device/program_store.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "device/device_context.h"
#include "device/kernel_sources.h"
#include "device/program_cache.h"
#include "render/feature_set.h"
#include "render/program_store_builder.h"
#include "support/opencl_test_device.h"
#include "support/scoped_env.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::ScopedEnv;
using testing::TempFolder;

FeatureSet spheres_only() {
    FeatureSet features;
    features.spheres = true;
    return features;
}

// Every file under `folder` with its bytes and modification time: what "never written" compares.
std::map<std::string, std::string> snapshot(const std::string& folder) {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(folder)) {
        std::ostringstream state;
        state << read_bytes(entry.path()) << "@" << fs::last_write_time(entry.path()).time_since_epoch().count();
        files[entry.path().string()] = state.str();
    }
    return files;
}

std::string only_entry(const std::string& folder) {
    std::string found;
    for (const auto& entry : fs::directory_iterator(folder)) {
        EXPECT_TRUE(found.empty()) << "one entry expected";
        found = entry.path().string();
    }
    return found;
}

TEST(ProgramStore, IsFoundBesideTheExecutableOrThroughTheEnvironment) {
    EXPECT_EQ(ProgramStore::folders_beside("/opt/clr/bin/clrender"),
              (std::vector<std::string>{"/opt/clr/share/clrender/programs", "/opt/clr/bin/share/clrender/programs"}));
    {
        ScopedEnv store("CLRENDER_PROGRAM_STORE", "/some/where");
        EXPECT_EQ(ProgramStore::from_environment().folder(), "/some/where");
    }
    for (const char* off : {"off", ""}) {
        ScopedEnv store("CLRENDER_PROGRAM_STORE", off);
        EXPECT_FALSE(ProgramStore::from_environment().enabled()) << "'" << off << "'";
    }
    // Unset: beside this test binary, in the build tree (where the build puts the store).
    ScopedEnv store("CLRENDER_PROGRAM_STORE", nullptr);
    const fs::path build_store = fs::read_symlink("/proc/self/exe").parent_path() / "share/clrender/programs";
    if (fs::is_directory(build_store))
        EXPECT_EQ(ProgramStore::from_environment().folder(), build_store.lexically_normal().string());
    else
        EXPECT_FALSE(ProgramStore::from_environment().enabled());
}

class ProgramStoreBuilds : public ::testing::Test {
protected:
    void SetUp() override {
        std::ostringstream log;
        const ProgramStoreBuild build = build_program_store(store_.path(), entry_, {spheres_only()}, log);
        ASSERT_EQ(build.built, 1) << log.str();
        ASSERT_EQ(build.failed, 0) << log.str();
    }

    const DeviceEntry& entry_ = testing::test_device().entry();
    const std::string source_ = assemble_program_source(kRenderTilesProgram.entry);
    const std::string options_ = spheres_only().build_options();
    TempFolder store_;
    TempFolder cache_;
    ScopedEnv cache_dir_{"CLRENDER_CACHE_DIR", cache_.path().c_str()};
};

TEST_F(ProgramStoreBuilds, AnEmptyCacheBuildsFromTheStoreAndTheStoreIsNeverWritten) {
    const auto before = snapshot(store_.path());
    {
        DeviceContext context(entry_, ProgramStore(store_.path()));
        cl::Program program = context.build_program(source_, options_);
        EXPECT_EQ(context.store_hits(), 1);
        EXPECT_EQ(context.cache_hits(), 0);
        EXPECT_NO_THROW(cl::Kernel(program, "render_packets"));
        context.store_built_programs();
    }
    EXPECT_FALSE(fs::exists(ProgramCache(cache_.path()).path(ProgramCache::key(entry_.device, source_, options_))))
        << "nothing built from source, nothing to keep";
    {
        // A miss in the store (other options) builds from source into the cache, not the store.
        DeviceContext context(entry_, ProgramStore(store_.path()));
        context.build_program(source_, options_ + " -DCLR_UNUSED=1");
        EXPECT_EQ(context.store_hits(), 0) << "other options, another key";
        context.store_built_programs();
    }
    EXPECT_TRUE(fs::exists(ProgramCache(cache_.path()).path(ProgramCache::key(entry_.device, source_, options_ + " -DCLR_UNUSED=1"))));
    EXPECT_EQ(snapshot(store_.path()), before);
}

TEST_F(ProgramStoreBuilds, TheCacheIsAskedFirst) {
    {
        ScopedEnv off("CLRENDER_CACHE_DIR", "off");
        DeviceContext context(entry_, ProgramStore(store_.path()));
        context.build_program(source_, options_);
        EXPECT_EQ(context.store_hits(), 1) << "with the caches off the store still serves";
    }
    {
        DeviceContext context(entry_);  // no store: built from source, kept in the cache
        context.build_program(source_, options_);
        context.store_built_programs();
    }
    DeviceContext context(entry_, ProgramStore(store_.path()));
    context.build_program(source_, options_);
    EXPECT_EQ(context.cache_hits(), 1);
    EXPECT_EQ(context.store_hits(), 0);
}

TEST_F(ProgramStoreBuilds, ADamagedEntryIsIgnoredAndLeftAlone) {
    const std::string path = only_entry(store_.path());
    std::string bytes = read_bytes(path);
    bytes[bytes.size() / 2] ^= 0x10;  // one byte in the binary
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
    const auto before = snapshot(store_.path());

    DeviceContext context(entry_, ProgramStore(store_.path()));
    cl::Program program = context.build_program(source_, options_);
    EXPECT_EQ(context.store_hits(), 0);
    EXPECT_NO_THROW(cl::Kernel(program, "render_packets")) << "built from source instead";
    EXPECT_EQ(snapshot(store_.path()), before) << "not removed, not repaired: the store is not the run's";
}

TEST_F(ProgramStoreBuilds, AnEntryForAnotherBuildMissesUnderAnyName) {
    // The entry of one build put under another build's name (another device, driver, source or
    // options has another key): the header's key does not match, so it is never used.
    const std::string path = only_entry(store_.path());
    const ProgramStore store(store_.path());
    const std::string other_source = source_ + "\n// another kernel version\n";
    fs::rename(path, store.path(ProgramCache::key(entry_.device, other_source, options_)));
    EXPECT_FALSE(store.load(ProgramCache::key(entry_.device, other_source, options_), ""));

    DeviceContext context(entry_, store);
    context.build_program(other_source, options_);
    EXPECT_EQ(context.store_hits(), 0);
}

TEST_F(ProgramStoreBuilds, TheBuilderKeepsGoodEntriesAndRemovesUnwantedOnes) {
    const std::string path = only_entry(store_.path());
    const std::string bytes = read_bytes(path);
    store_.write("notes.txt", "not an entry");
    FeatureSet other = spheres_only();
    other.sun = true;
    std::ostringstream log;
    ProgramStoreBuild again = build_program_store(store_.path(), entry_, {spheres_only()}, log);
    EXPECT_EQ(again.kept, 1);
    EXPECT_EQ(again.built, 0);
    EXPECT_EQ(read_bytes(path), bytes);
    again = build_program_store(store_.path(), entry_, {other}, log);
    EXPECT_EQ(again.built, 1);
    EXPECT_EQ(again.removed, 1);
    EXPECT_FALSE(fs::exists(path));
    EXPECT_TRUE(fs::exists(store_.file("notes.txt"))) << "only entries of ours are removed";
    EXPECT_EQ(empty_program_store(store_.path()), 1);
    EXPECT_EQ(store_.entry_count(), 1);
}

}  // namespace
}  // namespace clr
