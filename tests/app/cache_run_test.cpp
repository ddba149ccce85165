// The caches as a user meets them, through the real binary: a damaged or crafted program entry
// never makes a run wrong for more than the run it crashes in, and a cache folder that is full or
// read-only never makes a run fail.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/payload_checksum.h"
#include "core/sha256.h"
#include "support/command.h"
#include "support/obj_text.h"
#include "support/small_disk.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::run_clrender;
using testing::TempFolder;

constexpr std::size_t kHeaderBytes = 128;  // core/cache_entry.h

const char* kScene = R"({
  "eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
  "width": 40, "height": 30, "DefaultColor": [0.1, 0.1, 0.1],
  "spheres": [{"type": "sphere", "center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0, 0]}]
})";

std::vector<std::string> program_entries(const std::string& cache) {
    std::vector<std::string> entries;
    std::error_code error;
    for (fs::directory_iterator it(cache + "/programs", error), end; !error && it != end; it.increment(error))
        if (it->path().extension() == ".clbin") entries.push_back(it->path().string());
    return entries;
}

// A render of the scene with no cache at all: what every cached run must write too.
std::string reference_image(const TempFolder& folder) {
    EXPECT_EQ(run_clrender("scene.json -q -o reference.png", folder.path(), "CLRENDER_CACHE_DIR=off").exit_code, 0);
    return read_bytes(folder.file("reference.png"));
}

// `entry` with its payload replaced by `payload` and both checksums made right again: what
// someone who can write into the cache folder could plant.
void craft_entry(const std::string& entry, const std::string& payload) {
    std::string header = read_bytes(entry).substr(0, kHeaderBytes);
    const std::uint64_t size = payload.size();
    header.replace(24, 8, reinterpret_cast<const char*>(&size), 8);
    const PayloadChecksum checksum = payload_checksum(payload.data(), payload.size());
    header.replace(64, 16, reinterpret_cast<const char*>(checksum.data()), 16);
    const Sha256Digest header_digest = sha256(header.data(), 96);
    header.replace(96, 32, reinterpret_cast<const char*>(header_digest.data()), 32);
    std::ofstream(entry, std::ios::binary | std::ios::trunc) << header << payload;
}

TEST(CacheRun, ADamagedProgramEntryIsRebuiltAndReplaced) {
    TempFolder folder;
    folder.write("scene.json", kScene);
    const std::string reference = reference_image(folder);
    const std::string environment = "CLRENDER_CACHE_DIR='" + folder.file("cache") + "'";
    ASSERT_EQ(run_clrender("scene.json -q -o first.png", folder.path(), environment).exit_code, 0);
    const std::vector<std::string> entries = program_entries(folder.file("cache"));
    ASSERT_FALSE(entries.empty());
    std::vector<std::string> damaged;
    for (const std::string& entry : entries) {
        std::string bytes = read_bytes(entry);
        bytes[kHeaderBytes + (bytes.size() - kHeaderBytes) / 2] ^= 0x40;  // one byte in the binary
        std::ofstream(entry, std::ios::binary | std::ios::trunc) << bytes;
        damaged.push_back(bytes);
    }

    const auto second = run_clrender("scene.json -q -o second.png --stats stats.json", folder.path(), environment);
    ASSERT_EQ(second.exit_code, 0) << second.output;
    EXPECT_EQ(read_bytes(folder.file("second.png")), reference);
    EXPECT_NE(read_bytes(folder.file("stats.json")).find("\"cache_hits\": 0"), std::string::npos);
    for (std::size_t i = 0; i < entries.size(); ++i) {
        ASSERT_TRUE(fs::exists(entries[i]));
        EXPECT_NE(read_bytes(entries[i]), damaged[i]) << "replaced by a good entry";
    }
    const auto third = run_clrender("scene.json -q -o third.png --stats stats.json", folder.path(), environment);
    ASSERT_EQ(third.exit_code, 0) << third.output;
    EXPECT_EQ(read_bytes(folder.file("third.png")), reference);
    EXPECT_EQ(read_bytes(folder.file("stats.json")).find("\"cache_hits\": 0"), std::string::npos) << "hits again";
}

// A planted entry whose checksums are right: a binary of another kind is refused before the
// driver sees it; a driver binary cut short may still crash the one run that meets it (PoCL
// asserts on it), but never a later one.
TEST(CacheRun, ACraftedProgramEntryCostsAtMostOneRun) {
    TempFolder folder;
    folder.write("scene.json", kScene);
    const std::string reference = reference_image(folder);
    const std::string environment = "CLRENDER_CACHE_DIR='" + folder.file("cache") + "'";
    ASSERT_EQ(run_clrender("scene.json -q -o first.png", folder.path(), environment).exit_code, 0);
    const std::vector<std::string> entries = program_entries(folder.file("cache"));
    ASSERT_FALSE(entries.empty());
    const std::string good_binary = read_bytes(entries.front()).substr(kHeaderBytes);

    craft_entry(entries.front(), std::string(good_binary.size(), 'z'));  // not a binary of this driver
    auto run = run_clrender("scene.json -q -o foreign.png", folder.path(), environment);
    ASSERT_EQ(run.exit_code, 0) << run.output;
    EXPECT_EQ(read_bytes(folder.file("foreign.png")), reference);

    craft_entry(entries.front(), good_binary.substr(0, 100));  // the driver's magic, then cut short
    run_clrender("scene.json -q -o crafted.png", folder.path(), environment);  // may crash in the driver
    run = run_clrender("scene.json -q -o after.png", folder.path(), environment);
    ASSERT_EQ(run.exit_code, 0) << run.output;
    EXPECT_EQ(read_bytes(folder.file("after.png")), reference);
}

// Runs clrender with its cache folder on a private tmpfs of its own (a user namespace mounts it,
// so no privileges are needed) mounted with `mount_options`; false when this system does not
// allow that.
bool run_with_cache_on_tmpfs(const TempFolder& folder, const std::string& mount_options, const std::string& output,
                             testing::CommandResult& result) {
    if (!testing::can_mount_small_disks()) return false;
    const std::string cache = folder.file("cache");
    fs::create_directories(cache);
    const std::string wrapper = "CLRENDER_CACHE_DIR='" + cache + "' unshare -rm sh -c 'mount -t tmpfs -o " +
                                mount_options + " tmpfs \"$CLRENDER_CACHE_DIR\" && exec \"$0\" \"$@\"'";
    result = run_clrender("scene.json -q -o " + output + " --stats stats.json", folder.path(), wrapper);
    return true;
}

TEST(CacheRun, AFullOrReadOnlyCacheFolderLeavesTheRunSuccessful) {
    TempFolder folder;
    folder.write("scene.json", kScene);
    const std::string reference = reference_image(folder);
    for (const std::string& options : {std::string("size=16k,mode=700"), std::string("ro,mode=700")}) {
        testing::CommandResult result;
        if (!run_with_cache_on_tmpfs(folder, options, "out.png", result)) GTEST_SKIP() << "no user namespaces here";
        ASSERT_EQ(result.exit_code, 0) << options << ": " << result.output;
        EXPECT_EQ(read_bytes(folder.file("out.png")), reference) << options;
        fs::remove(folder.file("out.png"));
    }
}

TEST(CacheRun, ACacheFolderThatIsAFileLeavesTheRunSuccessful) {
    TempFolder folder;
    folder.write("scene.json", kScene);
    const std::string reference = reference_image(folder);
    folder.write("cache", "not a folder");
    const auto run = run_clrender("scene.json -q -o out.png", folder.path(), "CLRENDER_CACHE_DIR='" + folder.file("cache") + "'");
    ASSERT_EQ(run.exit_code, 0) << run.output;
    EXPECT_EQ(read_bytes(folder.file("out.png")), reference);
    EXPECT_EQ(read_bytes(folder.file("cache")), "not a folder");
}

// A large OBJ's parsed mesh comes from the cache on the second run (its entry's time is
// refreshed by the hit) and renders the image a run without any cache renders.
TEST(MeshCacheRun, ASecondRunTakesTheParsedMeshAndRendersTheSameImage) {
    TempFolder folder;
    folder.write("grid.obj", testing::grid_obj_text(160));
    folder.write("grid.mtl", "newmtl green\nKd 0.1 0.7 0.2\n");
    folder.write("scene.json", R"({
  "eye": [20, 6, 8], "lookat": [20, 0, -40], "up": [0, 1, 0], "fov_angle": 60,
  "width": 48, "height": 32, "DefaultColor": [0.1, 0.1, 0.3], "SunLocation": [30, 40, 10],
  "obj": {"type": "obj", "filename": "grid.obj"}})");
    const std::string reference = reference_image(folder);
    const std::string cache = folder.file("cache");
    const std::string environment = "CLRENDER_CACHE_DIR='" + cache + "'";
    ASSERT_EQ(run_clrender("scene.json -q -o first.png", folder.path(), environment).exit_code, 0);
    std::vector<fs::path> entries;
    for (const auto& entry : fs::directory_iterator(cache + "/meshes")) entries.push_back(entry.path());
    ASSERT_EQ(entries.size(), 1u);
    const auto long_ago = fs::file_time_type::clock::now() - std::chrono::hours(24 * 365);
    fs::last_write_time(entries[0], long_ago);
    struct stat before {};
    ASSERT_EQ(::stat(entries[0].c_str(), &before), 0);
    ASSERT_EQ(run_clrender("scene.json -q -o second.png", folder.path(), environment).exit_code, 0);
    // Used, not stored again: the same file (a store renames a new one into place), its time
    // refreshed by the hit.
    struct stat after {};
    ASSERT_EQ(::stat(entries[0].c_str(), &after), 0);
    EXPECT_EQ(after.st_ino, before.st_ino) << "the entry was replaced, not used";
    EXPECT_GT(fs::last_write_time(entries[0]), long_ago) << "the entry was used";
    EXPECT_EQ(read_bytes(folder.file("first.png")), reference);
    EXPECT_EQ(read_bytes(folder.file("second.png")), reference);
}

}  // namespace
}  // namespace clr
