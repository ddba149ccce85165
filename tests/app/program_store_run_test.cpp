// The program store as a user meets it, through the real binary: a first run with an empty
// cache builds nothing from source when the store has its program, writes the same image as a
// run that compiles, and a damaged store entry only means compiling, never a wrong image or a
// changed store. A still whose own program is in neither takes the store's general program
// (FeatureSet::general) and writes the same image; an animation compiles its own.
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

// The general program that stands in for a scene with point lights (and mirrors), without clipping.
FeatureSet general_with_lights() {
    FeatureSet lit;
    lit.lights = true;
    return FeatureSet::general(lit);
}

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

// A lit sphere on a plane (the fall 2019 format): planes and lights, whose feature sets the store
// holds no specialised program for; with a camera path of two keys when `frames` is 2.
std::string lit_plane_scene(int frames) {
    const std::string camera = frames == 1 ? R"("eye": [5, 5, 25], "lookat": [0, 0, 0],)"
                                           : R"("eyeLocations": [[5, 5, 25], [6, 5, 24]], "lookat": [0, 0, 0],)";
    return "{" + camera + R"( "up": [0, 1, 0], "fov_angle": 60, "width": 48, "height": 36,
  "surfaces": [
    {"type": "sphere", "center": [0, 6, 0], "radius": 6, "ambient": [0.2, 0.1, 0.05],
     "diffuse": [0.75, 0.5, 0.25], "specular": [0.75, 0.75, 0.75], "phong_exponent": 20, "mirror": [0.2, 0.2, 0.2]},
    {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "ambient": [0.1, 0.1, 0.1],
     "diffuse": [0.5, 0.5, 0.5], "specular": [0.1, 0.1, 0.1], "phong_exponent": 0}],
  "lights": [{"position": [30, 45, 10], "color": [0.8, 0.8, 0.8]}]})";
}

class GeneralStandIn : public ::testing::Test {
protected:
    void SetUp() override {
        folder_.write("still.json", lit_plane_scene(1));
        folder_.write("path.json", lit_plane_scene(2));
        std::ostringstream log;
        ASSERT_EQ(build_program_store(folder_.file("store"), testing::test_device().entry(),
                                      {general_with_lights()}, log)
                      .built,
                  1)
            << log.str();
        // References compiled from source, without cache or store.
        for (const char* arguments : {"still.json -q -o still-reference.png", "path.json -q -o path-reference_%04d.png"}) {
            const auto reference =
                run_clrender(arguments, folder_.path(), "CLRENDER_CACHE_DIR=off CLRENDER_PROGRAM_STORE=off");
            ASSERT_EQ(reference.exit_code, 0) << reference.output;
        }
    }

    // clrender ARGUMENTS with a fresh, empty cache and the store; its --stats.
    std::string run_with_store(const std::string& arguments, const std::string& cache) {
        const auto run = run_clrender(arguments + " -q --stats stats.json", folder_.path(),
                                      "CLRENDER_CACHE_DIR='" + folder_.file(cache) + "' CLRENDER_PROGRAM_STORE='" +
                                          folder_.file("store") + "'");
        EXPECT_EQ(run.exit_code, 0) << run.output;
        return read_bytes(folder_.file("stats.json"));
    }

    bool programs_cached(const std::string& cache) const {
        std::error_code error;
        return fs::exists(folder_.file(cache + "/programs")) && !fs::is_empty(folder_.file(cache + "/programs"), error);
    }

    TempFolder folder_;
};

TEST_F(GeneralStandIn, AStillTakesTheGeneralProgramAndWritesTheSameImage) {
    const std::string stats = run_with_store("still.json -o still.png", "cache-still");
    EXPECT_NE(stats.find("\"store_hits\": 1"), std::string::npos) << stats;
    EXPECT_EQ(read_bytes(folder_.file("still.png")), read_bytes(folder_.file("still-reference.png")));
    EXPECT_FALSE(programs_cached("cache-still")) << "nothing was compiled";
}

TEST_F(GeneralStandIn, AnAnimationCompilesItsOwnProgramAndKeepsIt) {
    const std::string stats = run_with_store("path.json -o path_%04d.png", "cache-path");
    EXPECT_NE(stats.find("\"store_hits\": 0"), std::string::npos) << stats;
    for (const char* frame : {"0000", "0001"})
        EXPECT_EQ(read_bytes(folder_.file(std::string("path_") + frame + ".png")),
                  read_bytes(folder_.file(std::string("path-reference_") + frame + ".png")));
    EXPECT_TRUE(programs_cached("cache-path"));
    // The next still of the same feature set takes that program from the cache, not the
    // general one from the store.
    const std::string still = run_with_store("still.json -o still.png", "cache-path");
    EXPECT_NE(still.find("\"cache_hits\": 1"), std::string::npos) << still;
    EXPECT_NE(still.find("\"store_hits\": 0"), std::string::npos) << still;
    EXPECT_EQ(read_bytes(folder_.file("still.png")), read_bytes(folder_.file("still-reference.png")));
}

}  // namespace
}  // namespace clr
