// Scene files that try to make clrender's messages unusable or render a wrong picture without
// an error: cameras that degenerate between path keys, a field of view narrower than float
// rays resolve, keys and strings that are megabytes long or hold terminal controls, and
// floods of warnings.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include <nlohmann/json.hpp>

#include "core/errors.h"
#include "scene/camera_path.h"
#include "scene/scene_loader.h"
#include "support/scene_json.h"

namespace clr {
namespace {

using Json = nlohmann::json;
using namespace testing::scene_json;

Json path_scene(const Json& eyes, const Json& lookats, const Json& settings = Json::object()) {
    Json json = minimal_scene();
    json.erase("eye");
    json.erase("lookat");
    json["eyeLocations"] = eyes;
    json["lookatLocations"] = lookats;
    json["clrender"] = settings;
    return json;
}

// The error a user sees for `text`, or "" when it loads.
std::string error_for(const std::string& text, const std::string& path = "test.json") {
    try {
        parse_scene(text, path, {});
    } catch (const SceneError& error) {
        return error.what();
    }
    return "";
}

// --- The camera between keys

TEST(HostileScene, EyePassingThroughTheLookatPointBetweenKeysIsAnError) {
    // Eye and look-at point swap places: at the middle frame they meet, though every key is fine.
    const Json json = path_scene({{0, 0, 0}, {2, 0, 0}}, {{2, 0, 0}, {0, 0, 0}}, {{"frames", 3}});
    EXPECT_TRUE(FailsAt(json, "/eyeLocations/0", "eye and lookat are the same point [1, 0, 0] at frame 1, between camera keys 0 and 1"));
    // With an even frame count no frame lands on the meeting point: the animation renders.
    EXPECT_NO_THROW(parse(path_scene({{0, 0, 0}, {2, 0, 0}}, {{2, 0, 0}, {0, 0, 0}}, {{"frames", 4}})));
}

TEST(HostileScene, ViewTurningParallelToUpBetweenKeysIsAnError) {
    // Keys look down and to the side; halfway the view is straight down, along -up.
    const Json json = path_scene({{-1, 0, 5}, {1, 0, 5}, {3, 0, 5}}, {{1, -5, 5}, {-1, -5, 5}, {-1, -5, 5}},
                                 {{"frames_per_segment", 2}});
    EXPECT_TRUE(FailsAt(json, "/eyeLocations/0", "is parallel to the view direction [0, -1, 0] at frame 1, between camera keys 0 and 1"));
}

TEST(HostileScene, CatmullRomPathPassingOverTheLookatPointIsAnError) {
    // The spline bulges out between keys 1 and 2 (its neighbours pull it towards +z), where a
    // straight line would not. The look-at point is put straight below the bulge's middle, so
    // that only the smooth path's frame 3 looks straight down, parallel to up.
    Json json = minimal_scene();
    json.erase("eye");
    json["eyeLocations"] = {{-2, 5, -1}, {-1, 5, 0}, {1, 5, 0}, {2, 5, -1}};
    json["clrender"] = {{"interpolation", "catmull-rom"}, {"frames_per_segment", 2}};
    json["lookat"] = {0, -50, 0};
    const Vec3 bulge = camera_at_frame(parse(json), 3).eye;
    ASSERT_GT(bulge.z, 0.01);
    json["lookat"] = {bulge.x, -50, bulge.z};
    EXPECT_TRUE(FailsAt(json, "/eyeLocations/1", "is parallel to the view direction [0, -1, 0] at frame 3, between camera keys 1 and 2"));
    json["clrender"]["interpolation"] = "linear";
    EXPECT_NO_THROW(parse(json));
}

TEST(HostileScene, LongPathsAreCheckedInLinearTime) {
    // 200001 keys, a million frames: camera_at_frame() once copied every key for each frame.
    Json eyes = Json::array();
    for (int i = 0; i <= 200000; ++i) eyes.push_back({i % 2, 0, 5});
    Json json = minimal_scene();
    json.erase("eye");
    json["eyeLocations"] = eyes;
    json["clrender"] = {{"frames", 1000000}};
    const auto start = std::chrono::steady_clock::now();
    EXPECT_NO_THROW(parse(json));
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(30));
}

// --- The field of view against the image size

TEST(HostileScene, FieldOfViewNarrowerThanFloatRaysResolveIsAnError) {
    Json json = minimal_scene();  // 4 x 3 pixels
    json["fov_angle"] = 1e-5;
    EXPECT_TRUE(FailsAt(json, "/fov_angle", "fov_angle 1e-5 is too narrow for a 4 x 3 image"));
    EXPECT_TRUE(FailsAt(json, "/fov_angle", "use a fov_angle of at least 0.00023 degrees"));
    json["fov_angle"] = 1e-300;
    EXPECT_TRUE(FailsAt(json, "/fov_angle", "too narrow"));
    json["fov_angle"] = 5e-324;
    EXPECT_TRUE(FailsAt(json, "/fov_angle", "too narrow"));
    // The suggested minimum itself passes.
    json["fov_angle"] = 0.00023;
    EXPECT_NO_THROW(parse(json));
}

TEST(HostileScene, TheLimitOnTheFieldOfViewFollowsTheImageSize) {
    Json json = minimal_scene();
    json["fov_angle"] = 0.5;
    EXPECT_NO_THROW(parse(json));
    LoadOptions huge;
    huge.width_override = 16384;
    huge.height_override = 4096;
    EXPECT_TRUE(FailsAt(json, "/fov_angle", "too narrow for a 16384 x 4096 image", huge));
    EXPECT_TRUE(FailsAt(json, "/fov_angle", "at least 0.94 degrees", huge));
}

// --- Messages that quote the file

TEST(HostileScene, AMegabyteKeyIsShortenedInTheMessage) {
    Json json = minimal_scene();
    json["clrender"] = {{"view_sets", {{std::string(1000000, 'v'), {{{"filename", ""}, {"direction", {0, 0, 1}}}}}}}};
    const std::string error = error_for(json.dump());
    EXPECT_NE(error.find("/clrender/view_sets/vvv"), std::string::npos) << error.substr(0, 300);
    EXPECT_NE(error.find("vvv/0/filename: filename must not be empty"), std::string::npos) << error.substr(0, 300);
    EXPECT_LT(error.size(), 700u);
}

TEST(HostileScene, AMegabyteStringBeforeASyntaxErrorIsShortened) {
    const std::string text = "{\"eye\": \"" + std::string(1000000, 'a') + "\xFF\"}";
    const std::string error = error_for(text);
    EXPECT_NE(error.find("line 1, column 1000010: "), std::string::npos) << error.substr(0, 300);
    EXPECT_NE(error.find("ill-formed UTF-8"), std::string::npos) << error.substr(0, 300);
    EXPECT_NE(error.find("aaa\\xFF'"), std::string::npos) << error.substr(0, 700);
    EXPECT_LT(error.size(), 700u);
}

TEST(HostileScene, TerminalControlsInValuesAndKeysAreEscaped) {
    Json json = minimal_scene();
    json["spheres"] = {sphere()};
    json["spheres"][0]["type"] = "\xC2\x9B" "31m\xE2\x80\xAE";
    const std::string error = error_for(json.dump());
    EXPECT_NE(error.find("got \"\\xC2\\x9B31m\\xE2\\x80\\xAE\""), std::string::npos) << error;

    json = minimal_scene();
    json["clrender"] = {{"view_sets", {{"a\xC2\x85\x1b", {{{"filename", ""}, {"direction", {0, 0, 1}}}}}}}};
    EXPECT_NE(error_for(json.dump()).find("/view_sets/a\\xC2\\x85\\x1B/0"), std::string::npos) << error_for(json.dump());
}

TEST(HostileScene, TheScenePathIsEscapedInMessages) {
    EXPECT_EQ(error_for("[]", "two\nlines\xC2\x9B.json").rfind("two\\x0Alines\\xC2\\x9B.json: ", 0), 0u);
}

TEST(HostileScene, WarningsStopAfterAHundredAndCountTheRest) {
    Json json = minimal_scene();
    for (int i = 0; i < 250; ++i) json["unknown_" + std::to_string(i)] = i;
    const Scene scene = parse(json);
    ASSERT_EQ(scene.warnings.size(), 101u);
    EXPECT_EQ(scene.warnings.back(), "150 more warnings not shown (only the first 100 are)");
    EXPECT_EQ(scene.warning_count, 250u) << "--check and --strict count every warning, not the lines shown";
}

TEST(HostileScene, ThousandsOfLongUnknownKeysLoadQuickly) {
    // Each unknown key is compared with the known ones for a "did you mean"; a long key must
    // not be compared letter by letter (60000 keys of 1000 letters once took 14 s).
    Json json = minimal_scene();
    for (int i = 0; i < 20000; ++i) json[std::string(1000, 'k') + std::to_string(i)] = 0;
    const auto start = std::chrono::steady_clock::now();
    EXPECT_NO_THROW(parse(json));
    // A bound, not a timing: letter-by-letter comparison of these keys is billions of steps
    // (minutes). AddressSanitizer's build runs several times slower, and CI's machine is shared.
#ifdef __SANITIZE_ADDRESS__
    const auto bound = std::chrono::seconds(30);
#else
    const auto bound = std::chrono::seconds(3);
#endif
    EXPECT_LT(std::chrono::steady_clock::now() - start, bound);
}

}  // namespace
}  // namespace clr
