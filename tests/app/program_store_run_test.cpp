// The program store as a user meets it, through the real binary: a first run with an empty
// cache builds nothing from source when the store has its program, writes the same image as a
// run that compiles, and a damaged store entry only means compiling, never a wrong image or a
// changed store.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "render/feature_set.h"
#include "render/program_store_builder.h"
#include "support/command.h"
#include "support/opencl_test_device.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::run_clrender;
using testing::TempFolder;

const char* kScene = R"({
  "eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
  "width": 40, "height": 30, "DefaultColor": [0.1, 0.1, 0.1],
  "spheres": [{"type": "sphere", "center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0, 0]}]
})";

class ProgramStoreRun : public ::testing::Test {
protected:
    void SetUp() override {
        folder_.write("scene.json", kScene);
        FeatureSet features;  // the scene's: one unlit sphere
        features.spheres = true;
        std::ostringstream log;
        ASSERT_EQ(build_program_store(folder_.file("store"), testing::test_device().entry(), {features}, log).built, 1)
            << log.str();
        const auto reference = run_clrender("scene.json -q -o reference.png", folder_.path(),
                                            "CLRENDER_CACHE_DIR=off CLRENDER_PROGRAM_STORE=off");
        ASSERT_EQ(reference.exit_code, 0) << reference.output;
    }

    // A run with a fresh, empty cache and the store; its --stats.
    std::string run_with_store(const std::string& output) {
        const std::string cache = folder_.file("cache-" + output);
        const auto run = run_clrender("scene.json -q -o " + output + " --stats stats.json", folder_.path(),
                                      "CLRENDER_CACHE_DIR='" + cache + "' CLRENDER_PROGRAM_STORE='" +
                                          folder_.file("store") + "'");
        EXPECT_EQ(run.exit_code, 0) << run.output;
        EXPECT_EQ(read_bytes(folder_.file(output)), read_bytes(folder_.file("reference.png"))) << output;
        return read_bytes(folder_.file("stats.json"));
    }

    std::string store_entry() const {
        for (const auto& entry : fs::directory_iterator(folder_.file("store"))) return entry.path().string();
        return "";
    }

    TempFolder folder_;
};

TEST_F(ProgramStoreRun, AFirstRunBuildsNothingFromSource) {
    const std::string stats = run_with_store("first.png");
    EXPECT_NE(stats.find("\"store_hits\": 1"), std::string::npos) << stats;
    EXPECT_NE(stats.find("\"cache_hits\": 0"), std::string::npos) << stats;
    std::error_code error;
    EXPECT_TRUE(!fs::exists(folder_.file("cache-first.png/programs")) ||
                fs::is_empty(folder_.file("cache-first.png/programs"), error))
        << "nothing was compiled, so nothing is kept in the cache";
}

TEST_F(ProgramStoreRun, ADamagedEntryIsIgnoredAndTheImageIsTheSame) {
    const std::string entry = store_entry();
    std::string bytes = read_bytes(entry);
    bytes[bytes.size() - bytes.size() / 3] ^= 0x01;
    std::ofstream(entry, std::ios::binary | std::ios::trunc) << bytes;

    const std::string stats = run_with_store("damaged.png");
    EXPECT_NE(stats.find("\"store_hits\": 0"), std::string::npos) << stats;
    EXPECT_EQ(read_bytes(entry), bytes) << "left as it was: the store is never written";
}

}  // namespace
}  // namespace clr
