// The scene loader: every key, variant and default of docs/scene-format.md, and every
// validation error with the JSON location and message a user sees.
#include "scene/scene_loader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/errors.h"
#include "support/scene_json.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using testing::TempFolder;
using namespace testing::scene_json;

// ---------------------------------------------------------------------------------------
// Keys and defaults

TEST(SceneLoader, MinimalSceneGetsDefaults) {
    const Scene scene = parse(minimal_scene());
    ASSERT_EQ(scene.camera_path.size(), 1u);
    EXPECT_EQ(scene.camera_path[0].eye, Vec3(0, 0, 5));
    EXPECT_EQ(scene.camera_path[0].lookat, Vec3(0, 0, 0));
    EXPECT_EQ(scene.up, Vec3(0, 1, 0));
    EXPECT_EQ(scene.fov_degrees, 60);
    EXPECT_EQ(scene.width, 4);
    EXPECT_EQ(scene.height, 3);
    EXPECT_EQ(scene.background, Vec3(0, 0, 0));
    EXPECT_FALSE(scene.only_ambient);
    EXPECT_FALSE(scene.has_sun);
    EXPECT_FALSE(scene.lit());
    EXPECT_EQ(scene.max_depth, 5);
    EXPECT_TRUE(scene.spheres.empty());
    EXPECT_TRUE(scene.billboards.empty());
    EXPECT_FALSE(scene.is_animated());
    EXPECT_TRUE(scene.warnings.empty()) << all_warnings(scene);
}

TEST(SceneLoader, NameAndPathComeFromTheGivenPath) {
    const Scene scene = parse_scene(minimal_scene().dump(), "some/folder/my.scene.json");
    EXPECT_EQ(scene.path, "some/folder/my.scene.json");
    EXPECT_EQ(scene.name, "my.scene");
}

TEST(SceneLoader, ReadsBackgroundLightingAndDepth) {
    Json json = minimal_scene();
    json["DefaultColor"] = {0.25, 0.5, 1};
    json["SunLocation"] = {-900, 900, 0};
    json["OnlyAmbient"] = 0;
    json["MaxDepth"] = 6;
    const Scene scene = parse(json);
    EXPECT_EQ(scene.background, Vec3(0.25, 0.5, 1));
    EXPECT_TRUE(scene.has_sun);
    EXPECT_EQ(scene.sun_location, Vec3(-900, 900, 0));
    EXPECT_FALSE(scene.only_ambient);
    EXPECT_TRUE(scene.lit());
    EXPECT_EQ(scene.max_depth, 6);
}

TEST(SceneLoader, AcceptsTheCourseSpellingDefaulColor) {
    Json json = minimal_scene();
    json["DefaulColor"] = {1.0, 0.9, 0.9};
    const Scene scene = parse(json);
    EXPECT_EQ(scene.background, Vec3(1.0, 0.9, 0.9));
    EXPECT_TRUE(scene.warnings.empty()) << all_warnings(scene);
}

TEST(SceneLoader, RejectsBothBackgroundSpellings) {
    Json json = minimal_scene();
    json["DefaulColor"] = {1, 1, 1};
    json["DefaultColor"] = {0, 0, 0};
    EXPECT_TRUE(FailsAt(json, "/DefaulColor", "both 'DefaultColor' and 'DefaulColor'"));
}

TEST(SceneLoader, OnlyAmbientTakesNumbersAndBooleans) {
    for (const Json& value : {Json(1), Json(true), Json(1.0)}) {
        Json json = minimal_scene();
        json["OnlyAmbient"] = value;
        json["SunLocation"] = {0, 10, 0};
        const Scene scene = parse(json);
        EXPECT_TRUE(scene.only_ambient) << value;
        EXPECT_FALSE(scene.lit()) << value;
    }
    for (const Json& value : {Json(0), Json(false)}) {
        Json json = minimal_scene();
        json["OnlyAmbient"] = value;
        EXPECT_FALSE(parse(json).only_ambient) << value;
    }
}

TEST(SceneLoader, RejectsFlagsOtherThanZeroOrOne) {
    Json json = minimal_scene();
    json["OnlyAmbient"] = 2;
    EXPECT_TRUE(FailsAt(json, "/OnlyAmbient", "OnlyAmbient must be 0, 1, false or true (got 2)"));
    json["OnlyAmbient"] = "yes";
    EXPECT_TRUE(FailsAt(json, "/OnlyAmbient", "(got \"yes\")"));
    json = minimal_scene();
    json["spheres"] = {sphere()};
    json["spheres"][0]["IsMirror"] = 0.5;
    EXPECT_TRUE(FailsAt(json, "/spheres/0/IsMirror", "IsMirror must be 0, 1, false or true"));
}

TEST(SceneLoader, MaxDepthIsAWholeNumberFromZeroTo64) {
    for (int depth : {0, 64}) {
        Json json = minimal_scene();
        json["MaxDepth"] = depth;
        EXPECT_EQ(parse(json).max_depth, depth);
    }
    for (const Json& value : {Json(-1), Json(65), Json(2.5)}) {
        Json json = minimal_scene();
        json["MaxDepth"] = value;
        EXPECT_TRUE(FailsAt(json, "/MaxDepth", "MaxDepth must be a whole number from 0 to 64")) << value;
    }
}

TEST(SceneLoader, KeyOrderIsFree) {
    const std::string text = R"({"spheres": [{"ambient": [1, 0, 0], "radius": 2, "center": [1, 2, 3],
        "type": "sphere"}], "height": 3, "fov_angle": 45, "up": [0, 1, 0], "width": 4,
        "lookat": [0, 0, 0], "eye": [0, 0, 5]})";
    const Scene scene = parse_scene(text, "test.json");
    ASSERT_EQ(scene.spheres.size(), 1u);
    EXPECT_EQ(scene.spheres[0].center, Vec3(1, 2, 3));
    EXPECT_EQ(scene.spheres[0].radius, 2);
    EXPECT_EQ(scene.fov_degrees, 45);
}

// ---------------------------------------------------------------------------------------
// Spheres

TEST(SceneLoader, ReadsSpheres) {
    Json json = minimal_scene();
    json["spheres"] = {sphere(1.5), sphere(0.25), sphere(2)};
    json["spheres"][1]["IsMirror"] = 1;
    json["spheres"][2]["IsMirror"] = true;
    json["spheres"][2].erase("type");  // "type" is optional
    json["spheres"][0]["center"] = {4, 0, 3};
    json["spheres"][0]["ambient"] = {0.09, 0.99, 0.09};
    const Scene scene = parse(json);
    ASSERT_EQ(scene.spheres.size(), 3u);
    EXPECT_EQ(scene.spheres[0].center, Vec3(4, 0, 3));
    EXPECT_EQ(scene.spheres[0].radius, 1.5);
    EXPECT_EQ(scene.spheres[0].ambient, Vec3(0.09, 0.99, 0.09));
    EXPECT_FALSE(scene.spheres[0].is_mirror);
    EXPECT_TRUE(scene.spheres[1].is_mirror);
    EXPECT_TRUE(scene.spheres[2].is_mirror);
    EXPECT_TRUE(scene.warnings.empty()) << all_warnings(scene);
}

TEST(SceneLoader, EmptyObjectListsAreFine) {
    Json json = minimal_scene();
    json["spheres"] = Json::array();
    json["billboards"] = Json::array();
    const Scene scene = parse(json);
    EXPECT_TRUE(scene.spheres.empty());
    EXPECT_TRUE(scene.billboards.empty());
}

TEST(SceneLoader, SphereNeedsCenterRadiusAndAmbient) {
    for (const char* key : {"center", "radius", "ambient"}) {
        Json json = minimal_scene();
        json["spheres"] = {sphere(), sphere()};
        json["spheres"][1].erase(key);
        EXPECT_TRUE(FailsAt(json, "/spheres/1", std::string("sphere is missing required key '") + key + "'"));
    }
}

TEST(SceneLoader, RejectsRadiusNotAboveZero) {
    Json json = minimal_scene();
    json["spheres"] = {sphere(), sphere(), sphere(), sphere(-1)};
    EXPECT_TRUE(FailsAt(json, "/spheres/3/radius", "radius must be > 0 (got -1)"));
    json["spheres"][3]["radius"] = 0;
    EXPECT_TRUE(FailsAt(json, "/spheres/3/radius", "radius must be > 0 (got 0)"));
}

TEST(SceneLoader, RejectsAWrongObjectType) {
    Json json = minimal_scene();
    json["spheres"] = {sphere()};
    json["spheres"][0]["type"] = "plane";
    EXPECT_TRUE(FailsAt(json, "/spheres/0/type", "type must be \"sphere\" here, got \"plane\""));
    json["spheres"][0]["type"] = 1;
    EXPECT_TRUE(FailsAt(json, "/spheres/0/type", "type must be a string, got 1"));

    json = minimal_scene();
    json["billboards"] = {flat_billboard()};
    json["billboards"][0]["type"] = "sphere";
    EXPECT_TRUE(FailsAt(json, "/billboards/0/type", "type must be \"billboard\" (or \"billboards\")"));
}

// ---------------------------------------------------------------------------------------
// Billboards

TEST(SceneLoader, ReadsFlatBillboardsWithEitherTypeName) {
    Json json = minimal_scene();
    json["billboards"] = {flat_billboard(), flat_billboard(), flat_billboard()};
    json["billboards"][1]["type"] = "billboards";
    json["billboards"][2].erase("type");
    json["billboards"][2]["IsMirror"] = 0;
    const Scene scene = parse(json);
    ASSERT_EQ(scene.billboards.size(), 3u);
    const Billboard& billboard = scene.billboards[0];
    EXPECT_EQ(billboard.upper_left, Vec3(-1, 1, 0));
    EXPECT_EQ(billboard.lower_left, Vec3(-1, -1, 0));
    EXPECT_EQ(billboard.upper_right, Vec3(1, 1, 0));
    EXPECT_TRUE(billboard.has_ambient);
    EXPECT_EQ(billboard.ambient, Vec3(0, 1, 0));
    EXPECT_EQ(billboard.image, nullptr);
    EXPECT_FALSE(billboard.is_mirror);
    EXPECT_TRUE(scene.warnings.empty()) << all_warnings(scene);
}

TEST(SceneLoader, BillboardNeedsItsThreeCorners) {
    for (const char* key : {"UpperLeft", "LowerLeft", "UpperRight"}) {
        Json json = minimal_scene();
        json["billboards"] = {flat_billboard()};
        json["billboards"][0].erase(key);
        EXPECT_TRUE(FailsAt(json, "/billboards/0", std::string("billboard is missing required key '") + key + "'"));
    }
}

TEST(SceneLoader, BillboardNeedsFilenameOrAmbientUnlessMirror) {
    Json json = minimal_scene();
    json["billboards"] = {flat_billboard(), flat_billboard()};
    json["billboards"][1].erase("ambient");
    EXPECT_TRUE(FailsAt(json, "/billboards/1", "billboard needs 'filename' (an image) or 'ambient'"));

    json["billboards"][1]["IsMirror"] = 1;
    const Scene scene = parse(json);
    EXPECT_TRUE(scene.billboards[1].is_mirror);
    EXPECT_FALSE(scene.billboards[1].has_ambient);
}

TEST(SceneLoader, MirrorBillboardIgnoresItsImage) {
    Json json = minimal_scene();
    json["billboards"] = {flat_billboard()};
    json["billboards"][0]["filename"] = "this-file-does-not-exist.ppm";
    json["billboards"][0]["IsMirror"] = 1;
    const Scene scene = parse(json);  // no error although the file is missing
    EXPECT_TRUE(scene.billboards[0].is_mirror);
    EXPECT_EQ(scene.billboards[0].image, nullptr);
    EXPECT_TRUE(scene.warnings.empty()) << all_warnings(scene);
}

TEST(SceneLoader, RejectsDegenerateBillboards) {
    struct Case {
        Vec3 ul, ll, ur;
        const char* fragment;
    };
    const std::vector<Case> cases = {
        {{0, 0, 0}, {0, -1, 0}, {0, 0, 0}, "UpperRight is the same point as UpperLeft"},
        {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, "LowerLeft is the same point as UpperLeft"},
        {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, "UpperRight is the same point as UpperLeft"},
        {{0, 0, 0}, {2, 0, 0}, {1, 0, 0}, "collinear"},
        {{1e6, 1e6, 1e6}, {3e6, 3e6, 3e6}, {2e6, 2e6, 2e6}, "collinear"},
    };
    for (const Case& c : cases) {
        Json json = minimal_scene();
        json["billboards"] = {flat_billboard(), flat_billboard()};
        json["billboards"][1]["UpperLeft"] = {c.ul.x, c.ul.y, c.ul.z};
        json["billboards"][1]["LowerLeft"] = {c.ll.x, c.ll.y, c.ll.z};
        json["billboards"][1]["UpperRight"] = {c.ur.x, c.ur.y, c.ur.z};
        EXPECT_TRUE(FailsAt(json, "/billboards/1", c.fragment));
    }
}

TEST(SceneLoader, AcceptsThinOrTinyBillboards) {
    // The area test is relative to the sides, so scale alone never makes a billboard degenerate.
    Json json = minimal_scene();
    json["billboards"] = {flat_billboard(), flat_billboard()};
    json["billboards"][0]["UpperRight"] = {1000, 1, 0};
    json["billboards"][0]["LowerLeft"] = {-1, 0.999, 0};
    json["billboards"][1]["UpperLeft"] = {0, 1e-9, 0};
    json["billboards"][1]["LowerLeft"] = {0, 0, 0};
    json["billboards"][1]["UpperRight"] = {1e-9, 1e-9, 0};
    EXPECT_EQ(parse(json).billboards.size(), 2u);
}

TEST(SceneLoader, TopLevelBillboardKeyAddsOneBillboard) {
    Json json = minimal_scene();
    json["billboards"] = {flat_billboard()};
    json["billboard"] = flat_billboard();
    json["billboard"]["ambient"] = {0, 0, 1};
    const Scene scene = parse(json);
    ASSERT_EQ(scene.billboards.size(), 2u);
    EXPECT_EQ(scene.billboards[1].ambient, Vec3(0, 0, 1));  // after the list
    EXPECT_FALSE(scene.billboards[1].is_mirror);

    json["billboard"].erase("ambient");
    EXPECT_TRUE(FailsAt(json, "/billboard", "billboard needs 'filename'"));
}

TEST(SceneLoader, TopLevelMirrorKeyIsAMirrorBillboard) {
    Json json = minimal_scene();
    json["mirror"] = Json::parse(R"({"type": "billboards", "UpperLeft": [-9, 9, 0], "LowerLeft": [-9, -9, 0],
                                     "UpperRight": [9, 9, 0]})");
    json["billboard"] = flat_billboard();
    Scene scene = parse(json);
    ASSERT_EQ(scene.billboards.size(), 2u);
    EXPECT_FALSE(scene.billboards[0].is_mirror);
    EXPECT_TRUE(scene.billboards[1].is_mirror);  // "mirror" comes after "billboard"
    EXPECT_EQ(scene.billboards[1].upper_left, Vec3(-9, 9, 0));

    json["mirror"]["IsMirror"] = true;
    EXPECT_TRUE(parse(json).billboards[1].is_mirror);
    json["mirror"]["IsMirror"] = 0;
    EXPECT_TRUE(FailsAt(json, "/mirror/IsMirror", "a 'mirror' is always a mirror"));
    json["mirror"]["IsMirror"] = 1;
    json["mirror"]["UpperRight"] = {-9, 9, 0};
    EXPECT_TRUE(FailsAt(json, "/mirror", "billboard has no area"));
}

TEST(SceneLoader, RejectsAnEmptyFilename) {
    Json json = minimal_scene();
    json["billboards"] = {flat_billboard()};
    json["billboards"][0]["filename"] = "";
    EXPECT_TRUE(FailsAt(json, "/billboards/0/filename", "filename must not be empty"));
    json["billboards"][0]["filename"] = 7;
    EXPECT_TRUE(FailsAt(json, "/billboards/0/filename", "filename must be a string, got 7"));
}

// ---------------------------------------------------------------------------------------
// Images

TEST(SceneLoader, LoadsImagesRelativeToTheSceneFolder) {
    TempFolder folder;
    fs::create_directories(folder.file("textures"));
    write_ppm(folder, "textures/tex.ppm", 2, 3);
    Json json = minimal_scene();
    json["billboards"] = {flat_billboard()};
    json["billboards"][0]["filename"] = "textures/tex.ppm";
    const Scene scene = parse_scene(json.dump(), folder.file("scene.json"));
    const Billboard& billboard = scene.billboards[0];
    ASSERT_NE(billboard.image, nullptr);
    EXPECT_EQ(billboard.image->width, 2);
    EXPECT_EQ(billboard.image->height, 3);
    EXPECT_EQ(billboard.image->at(1, 2, 0), 0x10);
    // Image and ambient together: the image shows, the colour is kept as well.
    EXPECT_TRUE(billboard.has_ambient);
    EXPECT_EQ(billboard.ambient, Vec3(0, 1, 0));
}

TEST(SceneLoader, LoadsEachImageFileOnce) {
    TempFolder folder;
    write_ppm(folder, "a.ppm", 1, 1);
    write_ppm(folder, "b.ppm", 1, 1);
    std::filesystem::create_directories(folder.file("sub"));  // ".." is the system's: sub must exist
    Json json = minimal_scene();
    json["billboards"] = {flat_billboard(), flat_billboard(), flat_billboard()};
    json["billboards"][0]["filename"] = "a.ppm";
    json["billboards"][1]["filename"] = "./sub/../a.ppm";  // the same file, spelt differently
    json["billboards"][2]["filename"] = "b.ppm";
    const Scene scene = parse_scene(json.dump(), folder.file("scene.json"));
    ASSERT_NE(scene.billboards[0].image, nullptr);
    EXPECT_EQ(scene.billboards[0].image, scene.billboards[1].image);
    EXPECT_NE(scene.billboards[0].image, scene.billboards[2].image);
}

TEST(SceneLoader, UsesAbsoluteImagePathsAsGiven) {
    TempFolder folder;
    const std::string image = write_ppm(folder, "abs.ppm", 3, 1);
    Json json = minimal_scene();
    json["billboards"] = {flat_billboard()};
    json["billboards"][0]["filename"] = image;
    const Scene scene = parse_scene(json.dump(), "elsewhere/scene.json");
    ASSERT_NE(scene.billboards[0].image, nullptr);
    EXPECT_EQ(scene.billboards[0].image->width, 3);
}

TEST(SceneLoader, MissingImageIsAnErrorAtItsFilename) {
    TempFolder folder;
    Json json = minimal_scene();
    json["billboards"] = {flat_billboard(), flat_billboard()};
    json["billboards"][1]["filename"] = "missing.png";
    const std::string scene_path = folder.file("scene.json");
    const std::string resolved = folder.file("missing.png");
    EXPECT_TRUE(TextFailsAt(json.dump(), "/billboards/1/filename", "cannot read image '" + resolved + "': ", {},
                        scene_path));
}

TEST(SceneLoader, CorruptImageIsAnErrorAtItsFilename) {
    TempFolder folder;
    folder.write("bad.ppm", "P6\n2 2\n255\n\x01");  // truncated pixel data
    Json json = minimal_scene();
    json["billboards"] = {flat_billboard()};
    json["billboards"][0]["filename"] = "bad.ppm";
    EXPECT_TRUE(TextFailsAt(json.dump(), "/billboards/0/filename", "cannot read image '", {},
                        folder.file("scene.json")));
}

TEST(SceneLoader, MissingImageBecomesAPlaceholderWhenAsked) {
    TempFolder folder;
    Json json = minimal_scene();
    json["billboards"] = {flat_billboard(), flat_billboard()};
    json["billboards"][0]["filename"] = "missing.png";
    json["billboards"][1]["filename"] = "missing.png";
    LoadOptions options;
    options.placeholder_images = true;
    const Scene scene = parse_scene(json.dump(), folder.file("scene.json"), options);
    ASSERT_NE(scene.billboards[0].image, nullptr);
    EXPECT_EQ(scene.billboards[0].image, scene.billboards[1].image);
    EXPECT_TRUE(has_warning(scene, "/billboards/0/filename: cannot read image")) << all_warnings(scene);
    EXPECT_TRUE(has_warning(scene, "/billboards/1/filename: cannot read image")) << all_warnings(scene);
    EXPECT_TRUE(has_warning(scene, "placeholder")) << all_warnings(scene);
}

// ---------------------------------------------------------------------------------------
// Camera path

TEST(SceneLoader, EyeLocationsWithAFixedLookatMakeAPath) {
    Json json = minimal_scene();
    json.erase("eye");
    json["eyeLocations"] = {{-4.85, -0.29, 6.4}, {-6.37, 3.4, 1.06}, {0, 0, 9}};
    json["lookat"] = {0, 0, 3};
    const Scene scene = parse(json);
    ASSERT_EQ(scene.camera_path.size(), 3u);
    EXPECT_TRUE(scene.is_animated());
    EXPECT_EQ(scene.camera_path[1].eye, Vec3(-6.37, 3.4, 1.06));
    for (const CameraKey& key : scene.camera_path) EXPECT_EQ(key.lookat, Vec3(0, 0, 3));
}

TEST(SceneLoader, OneEyeLocationIsAStill) {
    Json json = minimal_scene();
    json.erase("eye");
    json["eyeLocations"] = {{0, 0, 5}};
    const Scene scene = parse(json);
    ASSERT_EQ(scene.camera_path.size(), 1u);
    EXPECT_FALSE(scene.is_animated());
    EXPECT_EQ(scene.camera_path[0].eye, Vec3(0, 0, 5));
}

TEST(SceneLoader, LookatLocationsPairWithEyeLocations) {
    Json json = minimal_scene();
    json.erase("eye");
    json.erase("lookat");
    json["eyeLocations"] = {{-1, 3.65, 20}, {0, 0, 20}};
    json["lookatLocations"] = {{3.86, 0, 0}, {0, 0, 0}};
    const Scene scene = parse(json);
    ASSERT_EQ(scene.camera_path.size(), 2u);
    EXPECT_EQ(scene.camera_path[0].lookat, Vec3(3.86, 0, 0));
    EXPECT_EQ(scene.camera_path[1].eye, Vec3(0, 0, 20));
    EXPECT_EQ(scene.camera_path[1].lookat, Vec3(0, 0, 0));
}

TEST(SceneLoader, RejectsLookatLocationsOfAnotherCount) {
    Json json = minimal_scene();
    json.erase("eye");
    json.erase("lookat");
    json["eyeLocations"] = {{0, 0, 5}, {0, 0, 6}};
    json["lookatLocations"] = {{0, 0, 0}, {0, 0, 1}, {0, 0, 2}};
    EXPECT_TRUE(FailsAt(json, "/lookatLocations", "lookatLocations has 3 entries but eyeLocations has 2 entries"));

    json = minimal_scene();
    json.erase("lookat");
    json["lookatLocations"] = {{0, 0, 0}, {0, 0, 1}};
    EXPECT_TRUE(FailsAt(json, "/lookatLocations", "but there is a single 'eye'"));
}

TEST(SceneLoader, RejectsBothFormsOfOneCameraKey) {
    Json json = minimal_scene();
    json["eyeLocations"] = {{0, 0, 5}};
    EXPECT_TRUE(FailsAt(json, "/eyeLocations", "give either 'eye' or 'eyeLocations', not both"));
    json = minimal_scene();
    json["lookatLocations"] = {{0, 0, 0}};
    EXPECT_TRUE(FailsAt(json, "/lookatLocations", "give either 'lookat' or 'lookatLocations', not both"));
}

TEST(SceneLoader, RejectsAnEmptyOrMalformedPath) {
    Json json = minimal_scene();
    json.erase("eye");
    json["eyeLocations"] = Json::array();
    EXPECT_TRUE(FailsAt(json, "/eyeLocations", "eyeLocations must hold at least one [x, y, z] position"));
    json["eyeLocations"] = {0, 0, 5};  // a point, not a list of points
    EXPECT_TRUE(FailsAt(json, "/eyeLocations/0", "eyeLocations[0] must be an array [x, y, z] of 3 numbers, got 0"));
    json["eyeLocations"] = {{0, 0, 5}, {0, 1}};
    EXPECT_TRUE(FailsAt(json, "/eyeLocations/1", "got an array of 2 values"));
}

TEST(SceneLoader, RequiresTheCameraKeys) {
    const std::vector<std::pair<const char*, const char*>> cases = {
        {"eye", "scene needs 'eye'"},
        {"lookat", "scene needs 'lookat'"},
        {"up", "scene is missing required key 'up'"},
        {"fov_angle", "scene is missing required key 'fov_angle'"},
        {"width", "scene is missing required key 'width' (or give the size on the command line"},
        {"height", "scene is missing required key 'height'"},
    };
    for (const auto& [key, fragment] : cases) {
        Json json = minimal_scene();
        json.erase(key);
        EXPECT_TRUE(FailsAt(json, "", fragment)) << key;
    }
}

TEST(SceneLoader, RejectsEyeAtLookat) {
    Json json = minimal_scene();
    json["eye"] = {1, 2, 3};
    json["lookat"] = {1, 2, 3};
    EXPECT_TRUE(FailsAt(json, "/eye", "eye and lookat are the same point [1, 2, 3]"));

    json.erase("eye");
    json["eyeLocations"] = {{0, 0, 5}, {0, 0, 6}, {1, 2, 3}};
    EXPECT_TRUE(FailsAt(json, "/eyeLocations/2", "at camera key 2"));

    json = minimal_scene();
    json.erase("lookat");
    json.erase("eye");
    json["eyeLocations"] = {{0, 0, 5}, {0, 0, 6}};
    json["lookatLocations"] = {{0, 0, 0}, {0, 0, 6}};
    EXPECT_TRUE(FailsAt(json, "/eyeLocations/1", "the same point"));
}

TEST(SceneLoader, RejectsAZeroUp) {
    Json json = minimal_scene();
    json["up"] = {0, 0, 0};
    EXPECT_TRUE(FailsAt(json, "/up", "up must not be the zero vector"));
}

TEST(SceneLoader, RejectsUpParallelToTheView) {
    Json json = minimal_scene();
    json["up"] = {0, 0, 3};  // the view runs along -z
    EXPECT_TRUE(FailsAt(json, "/up", "is parallel to the view direction"));
    json["up"] = {0, 0, -1e-3};
    EXPECT_TRUE(FailsAt(json, "/up", "is parallel to the view direction"));

    // On a path, the key where the view turns parallel to up is named.
    json = minimal_scene();
    json.erase("eye");
    json["eyeLocations"] = {{0, 0, 5}, {0, 7, 0}};
    EXPECT_TRUE(FailsAt(json, "/eyeLocations/1", "at camera key 1"));

    // One eye with a one-entry lookatLocations is a still: the error is at up.
    json = minimal_scene();
    json.erase("lookat");
    json["lookatLocations"] = {{0, 1e6, 5}};
    EXPECT_TRUE(FailsAt(json, "/up", "is parallel"));
    // ... but eye == lookat is found at the look-at entry.
    json["lookatLocations"] = {{0, 0, 5}};
    EXPECT_TRUE(FailsAt(json, "/lookatLocations/0", "eye and lookat are the same point"));
}

TEST(SceneLoader, AcceptsUpNearlyParallelToTheView) {
    // The test is on the angle, not on lengths: a large scene with a small tilt is fine.
    Json json = minimal_scene();
    json["eye"] = {0, 1e6, 0};
    json["lookat"] = {0, 0, 0};
    json["up"] = {1e-6, 1, 0};
    EXPECT_EQ(parse(json).up, Vec3(1e-6, 1, 0));
    json["up"] = {0, 1, 1e-20};
    json["eye"] = {0, 0, 1e-20};
    json["lookat"] = {0, 0, 0};
    EXPECT_EQ(parse(json).camera_path[0].eye, Vec3(0, 0, 1e-20));
}

TEST(SceneLoader, FovAngleIsBetween0And180) {
    for (double fov : {0.0, 180.0, -5.0, 200.0}) {
        Json json = minimal_scene();
        json["fov_angle"] = fov;
        EXPECT_TRUE(FailsAt(json, "/fov_angle", "fov_angle must be between 0 and 180 degrees")) << fov;
    }
    Json json = minimal_scene();
    json["fov_angle"] = 179.5;
    EXPECT_EQ(parse(json).fov_degrees, 179.5);
    json["fov_angle"] = "60";
    EXPECT_TRUE(FailsAt(json, "/fov_angle", "fov_angle must be a number, got \"60\""));
}

// ---------------------------------------------------------------------------------------
// Image size

TEST(SceneLoader, WidthAndHeightAreWholeNumbersFromOne) {
    Json json = minimal_scene();
    json["width"] = 600.0;  // integral, though written as a float
    EXPECT_EQ(parse(json).width, 600);
    for (const Json& value : {Json(0), Json(-1), Json(2.5), Json(16385)}) {
        json["height"] = value;
        EXPECT_TRUE(FailsAt(json, "/height", "height must be a whole number from 1 to 16384")) << value;
    }
    json["height"] = "600";
    EXPECT_TRUE(FailsAt(json, "/height", "height must be a number, got \"600\""));
}

TEST(SceneLoader, RejectsImagesOverThePixelLimit) {
    Json json = minimal_scene();
    json["width"] = 16384;
    json["height"] = 16384;
    EXPECT_TRUE(FailsAt(json, "/height", "more than the limit of 67108864"));
    json["height"] = 4096;  // exactly the limit
    EXPECT_EQ(parse(json).height, 4096);
}

TEST(SceneLoader, SizeOverridesReplaceTheScenesSize) {
    LoadOptions options;
    options.width_override = 500;
    options.height_override = 200;
    Json json = minimal_scene();
    json["width"] = "not even a number";  // replaced, so never read
    Scene scene = parse(json, options);
    EXPECT_EQ(scene.width, 500);
    EXPECT_EQ(scene.height, 200);

    json.erase("width");
    json.erase("height");
    scene = parse(json, options);
    EXPECT_EQ(scene.width, 500);
    EXPECT_TRUE(scene.warnings.empty()) << all_warnings(scene);

    options.height_override.reset();  // width from the command line, height from the scene
    json["height"] = 7;
    scene = parse(json, options);
    EXPECT_EQ(scene.width, 500);
    EXPECT_EQ(scene.height, 7);
}

TEST(SceneLoader, RejectsOverridesOutOfRange) {
    LoadOptions options;
    options.width_override = 0;
    EXPECT_TRUE(FailsAt(minimal_scene(), "", "image width 0 given on the command line", options));
    options.width_override = 16384;
    options.height_override = 16384;
    EXPECT_TRUE(FailsAt(minimal_scene(), "", "more than the limit", options));
}

// ---------------------------------------------------------------------------------------
// Values and types

TEST(SceneLoader, VectorsHaveExactlyThreeNumbers) {
    Json json = minimal_scene();
    json["eye"] = {1, 2};
    EXPECT_TRUE(FailsAt(json, "/eye", "eye must be an array [x, y, z] of 3 numbers, got an array of 2 values"));
    json["eye"] = {1, 2, 3, 4};
    EXPECT_TRUE(FailsAt(json, "/eye", "got an array of 4 values"));
    json["eye"] = {1, "2", 3};
    EXPECT_TRUE(FailsAt(json, "/eye/1", "eye[1] must be a number, got \"2\""));
    json["eye"] = "1,2,3";
    EXPECT_TRUE(FailsAt(json, "/eye", "eye must be an array [x, y, z] of 3 numbers, got \"1,2,3\""));
    json = minimal_scene();
    json["DefaultColor"] = {{"r", 1}};
    EXPECT_TRUE(FailsAt(json, "/DefaultColor", "must be an array [r, g, b] of 3 numbers, got an object"));
    json = minimal_scene();
    json["spheres"] = {sphere()};
    json["spheres"][0]["ambient"] = {1, 1, nullptr};
    EXPECT_TRUE(FailsAt(json, "/spheres/0/ambient/2", "ambient[2] must be a number, got null"));
}

TEST(SceneLoader, RejectsNumbersThatOverflow) {
    const std::string text = "{\"eye\": [0, 0, 5], \"lookat\": [0, 0, 0], \"up\": [0, 1, 0],\n"
                             "  \"fov_angle\": 60, \"width\": 4, \"height\": 3, \"SunLocation\": [1e999, 0, 0]}";
    EXPECT_TRUE(TextFailsAt(text, "", "line 2, column 61: number 1e999 is too large"));
    EXPECT_TRUE(TextFailsAt("{\"eye\": [-1E+400, 0, 0]}", "", "line 1, column 10: number -1E+400 is too large"));
}

TEST(SceneLoader, WrongJsonTypesNameTheExpectedType) {
    Json json = minimal_scene();
    json["spheres"] = sphere();
    EXPECT_TRUE(FailsAt(json, "/spheres", "spheres must be an array [ ... ], got an object"));
    json["spheres"] = {5};
    EXPECT_TRUE(FailsAt(json, "/spheres/0", "spheres[0] must be a JSON object { ... }, got 5"));
    json = minimal_scene();
    json["billboard"] = {flat_billboard()};
    EXPECT_TRUE(FailsAt(json, "/billboard", "billboard must be a JSON object { ... }, got an array of 1 value"));
    EXPECT_TRUE(TextFailsAt("[1, 2, 3]", "", "scene must be a JSON object { ... }, got an array of 3 values"));
    EXPECT_TRUE(TextFailsAt("\"a scene\"", "", "scene must be a JSON object"));
}

// ---------------------------------------------------------------------------------------
// JSON syntax and encoding

TEST(SceneLoader, SyntaxErrorsGiveLineAndColumn) {
    EXPECT_TRUE(TextFailsAt("{\n  \"eye\": [0, 0, 5],\n  \"up\" [0, 1, 0]\n}", "", "line 3, column 8: syntax error"));
    EXPECT_TRUE(TextFailsAt("{\"eye\": [0, 0, 5]", "", "line 1, column 18: syntax error"));
    // Columns count characters, not bytes: "é" is two bytes in UTF-8.
    EXPECT_TRUE(TextFailsAt("{\"é\": x}", "", "line 1, column 7:"));
    // Windows line endings count as one line break.
    EXPECT_TRUE(TextFailsAt("{\r\n\"a\": 1,\r\n\"b\": ?}", "", "line 3, column 6:"));
}

TEST(SceneLoader, SyntaxErrorExplainsATrailingComma) {
    EXPECT_TRUE(TextFailsAt("{\n  \"eye\": [0, 0, 5,],\n}", "", "line 2, column 19:"));
    EXPECT_TRUE(TextFailsAt("{\n  \"eye\": [0, 0, 5],\n}", "", "JSON allows no comma before '}' or ']'"));
}

TEST(SceneLoader, RejectsAnEmptyText) {
    EXPECT_TRUE(TextFailsAt("", "", "the file is empty"));
    EXPECT_TRUE(TextFailsAt("\xEF\xBB\xBF \r\n", "", "the file is empty"));
}

TEST(SceneLoader, AcceptsBomCrlfAndComments) {
    std::string text = "\xEF\xBB\xBF{\r\n";
    text += "  // the camera\r\n";
    text += "  \"eye\": [0, 0, 5], \"lookat\": [0, 0, 0], \"up\": [0, 1, 0],\r\n";
    text += "  /* image */ \"fov_angle\": 60, \"width\": 4, \"height\": 3\r\n}\r\n";
    const Scene scene = parse_scene(text, "test.json");
    EXPECT_EQ(scene.width, 4);
    EXPECT_TRUE(scene.warnings.empty()) << all_warnings(scene);
    // A BOM does not shift the reported column.
    EXPECT_TRUE(TextFailsAt("\xEF\xBB\xBF{,}", "", "line 1, column 2:"));
}

// ---------------------------------------------------------------------------------------
// Warnings

TEST(SceneLoader, UnknownKeysAreWarnedWithTheirLocation) {
    Json json = minimal_scene();
    json["spheres"] = {sphere()};
    json["spheres"][0]["colour"] = {1, 1, 1};
    json["billboards"] = {flat_billboard()};
    json["billboards"][0]["opacity"] = 1;
    json["animation"] = true;
    const Scene scene = parse(json);
    EXPECT_EQ(scene.warnings.size(), 3u) << all_warnings(scene);
    EXPECT_TRUE(has_warning(scene, "/spheres/0/colour: unknown key (ignored)")) << all_warnings(scene);
    EXPECT_TRUE(has_warning(scene, "/billboards/0/opacity: unknown key (ignored)")) << all_warnings(scene);
    EXPECT_TRUE(has_warning(scene, "/animation: unknown key (ignored)")) << all_warnings(scene);
}

TEST(SceneLoader, UnknownKeyWarningSuggestsTheKeyMeant) {
    Json json = minimal_scene();
    json["spheres"] = {sphere()};
    json["spheres"][0]["radious"] = 2;
    json["sunLocation"] = {0, 1, 0};
    json["Maxdepth"] = 3;
    json["a/b"] = 1;  // a key that needs escaping in a JSON pointer
    const Scene scene = parse(json);
    EXPECT_TRUE(has_warning(scene, "/spheres/0/radious: unknown key (ignored); did you mean 'radius'?"))
        << all_warnings(scene);
    EXPECT_TRUE(has_warning(scene, "/sunLocation: unknown key (ignored); did you mean 'SunLocation'?"))
        << all_warnings(scene);
    EXPECT_TRUE(has_warning(scene, "did you mean 'MaxDepth'?")) << all_warnings(scene);
    EXPECT_TRUE(has_warning(scene, "/a~1b: unknown key (ignored)")) << all_warnings(scene);
    EXPECT_FALSE(scene.has_sun);
}

TEST(SceneLoader, NearAndFarAreClipDepths) {
    Json json = minimal_scene();
    EXPECT_FALSE(parse(json).clips()) << "by default everything is seen";
    json["near"] = 3;
    json["far"] = 20;
    Scene scene = parse(json);
    EXPECT_TRUE(scene.warnings.empty()) << all_warnings(scene);
    EXPECT_EQ(scene.clip_near, 3);
    EXPECT_EQ(scene.clip_far, 20);
    json.erase("far");
    scene = parse(json);
    EXPECT_EQ(scene.clip_far, std::numeric_limits<double>::infinity()) << "near alone";
    json["near"] = -1;
    EXPECT_TRUE(FailsAt(json, "/near", "near must be from 0 to 1e16, got -1"));
    json["near"] = 5;
    json["far"] = 5;
    EXPECT_TRUE(FailsAt(json, "/far", "far must be greater than near (5) and at most 1e16, got 5"));
    json["far"] = 1e300;
    EXPECT_TRUE(FailsAt(json, "/far", "got 1e300"));
    json["far"] = "20";
    EXPECT_TRUE(FailsAt(json, "/far", "must be a number"));
}

TEST(SceneLoader, ExtensionsDefaultToTheCoursesAnimation) {
    const Scene scene = parse(minimal_scene());
    EXPECT_EQ(scene.animation.frames_per_segment, 10);
    EXPECT_EQ(scene.animation.frame_count, 0);
    EXPECT_EQ(scene.animation.fps, 10);
    EXPECT_EQ(scene.animation.interpolation, Interpolation::Linear);
}

TEST(SceneLoader, ReadsAnimationExtensions) {
    Json json = minimal_scene();
    json["clrender"] = {{"fps", 24}, {"frames", 48}, {"interpolation", "catmull-rom"}};
    Scene scene = parse(json);
    EXPECT_EQ(scene.animation.fps, 24);
    EXPECT_EQ(scene.animation.frame_count, 48);
    EXPECT_EQ(scene.animation.interpolation, Interpolation::CatmullRom);
    EXPECT_TRUE(scene.warnings.empty()) << all_warnings(scene);

    json["clrender"] = {{"fps", 30}, {"duration", 2.5}};
    EXPECT_EQ(parse(json).animation.frame_count, 75);
    json["clrender"] = {{"frames_per_segment", 4}};
    EXPECT_EQ(parse(json).animation.frames_per_segment, 4);
}

TEST(SceneLoader, RejectsBadAnimationExtensions) {
    Json json = minimal_scene();
    json["clrender"] = {{"fps", 0}};
    EXPECT_TRUE(FailsAt(json, "/clrender/fps", "fps must be in (0, 1000]"));
    json["clrender"] = {{"interpolation", "cubic"}};
    EXPECT_TRUE(FailsAt(json, "/clrender/interpolation", "\"linear\" or \"catmull-rom\""));
    json["clrender"] = {{"frames", 1}};
    EXPECT_TRUE(FailsAt(json, "/clrender/frames", "frames"));
    json["clrender"] = {{"frames", 10}, {"duration", 1}};
    EXPECT_TRUE(FailsAt(json, "/clrender", "one way only"));
    json["clrender"] = {{"duration", -1}};
    EXPECT_TRUE(FailsAt(json, "/clrender/duration", "duration must give"));
    json["clrender"] = 3;
    EXPECT_TRUE(FailsAt(json, "/clrender", "object"));
}

TEST(SceneLoader, ReadsSamplingExtensionsAndTheOverride) {
    Json json = minimal_scene();
    EXPECT_EQ(parse(json).sampling.samples_per_pixel, 1);
    json["clrender"] = {{"spp", 9}, {"seed", 42}};
    Scene scene = parse(json);
    EXPECT_EQ(scene.sampling.samples_per_pixel, 9);
    EXPECT_EQ(scene.sampling.seed, 42u);
    LoadOptions options;
    options.samples_override = 3;
    EXPECT_EQ(parse(json, options).sampling.samples_per_pixel, 3);
    json["clrender"] = {{"spp", 0}};
    EXPECT_TRUE(FailsAt(json, "/clrender/spp", "spp"));
    json["clrender"] = {{"seed", -1}};
    EXPECT_TRUE(FailsAt(json, "/clrender/seed", "seed"));
}

TEST(SceneLoader, UnknownExtensionKeysAreWarned) {
    Json json = minimal_scene();
    json["clrender"] = {{"fsp", 24}};
    const Scene scene = parse(json);
    EXPECT_TRUE(has_warning(scene, "/clrender/fsp: unknown key")) << all_warnings(scene);
}

TEST(SceneLoader, DuplicateKeysAreWarnedAndTheLastWins) {
    const std::string text = R"({"eye": [0, 0, 5], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
        "width": 4, "height": 3, "width": 8,
        "spheres": [{"center": [0, 0, 0], "radius": 1, "ambient": [1, 0, 0]},
                    {"center": [0, 0, 0], "radius": 1, "radius": 2, "ambient": [1, 0, 0]}]})";
    const Scene scene = parse_scene(text, "test.json");
    EXPECT_EQ(scene.width, 8);
    EXPECT_EQ(scene.spheres[1].radius, 2);
    EXPECT_TRUE(has_warning(scene, "/width: duplicate key (the last value is used)")) << all_warnings(scene);
    EXPECT_TRUE(has_warning(scene, "/spheres/1/radius: duplicate key")) << all_warnings(scene);
    EXPECT_EQ(scene.warnings.size(), 2u) << all_warnings(scene);
}

// ---------------------------------------------------------------------------------------
// Files

TEST(SceneLoader, LoadSceneReadsAFile) {
    TempFolder folder;
    write_ppm(folder, "tex.ppm", 1, 1);
    Json json = minimal_scene();
    json["billboards"] = {flat_billboard()};
    json["billboards"][0]["filename"] = "tex.ppm";
    const std::string path = folder.write("still.js", json.dump(2));
    const Scene scene = load_scene(path);
    EXPECT_EQ(scene.path, path);
    EXPECT_EQ(scene.name, "still");
    ASSERT_NE(scene.billboards[0].image, nullptr);
}

TEST(SceneLoader, LoadSceneRejectsMissingFilesAndFolders) {
    TempFolder folder;
    const std::string missing = folder.file("missing.json");
    try {
        load_scene(missing);
        ADD_FAILURE() << "no SceneError";
    } catch (const SceneError& error) {
        EXPECT_EQ(error.file(), missing);
        EXPECT_EQ(error.location(), "");
        EXPECT_NE(error.detail().find("cannot read scene file"), std::string::npos) << error.detail();
        EXPECT_EQ(error.code(), kExitScene);
    }
    try {
        load_scene(folder.path());
        ADD_FAILURE() << "no SceneError";
    } catch (const SceneError& error) {
        EXPECT_NE(error.detail().find("cannot read scene file: it is a folder"), std::string::npos) << error.detail();
    }
}

TEST(SceneLoader, ErrorMessageNamesFileLocationAndDetail) {
    Json json = minimal_scene();
    json["spheres"] = {sphere(-1)};
    try {
        parse_scene(json.dump(), "scenes/bad.json");
        ADD_FAILURE() << "no SceneError";
    } catch (const SceneError& error) {
        EXPECT_STREQ(error.what(), "scenes/bad.json: /spheres/0/radius: radius must be > 0 (got -1)");
    }
}

// ---------------------------------------------------------------------------------------
// The course's own scenes (read from the shared folder, never copied into the project)

const fs::path kCourseScenes = fs::path(CLRENDER_SOURCE_DIR) / ".." / "shared" / "course-scenes";

Scene load_course_scene(const std::string& relative_path, LoadOptions options = {}) {
    return load_scene((kCourseScenes / relative_path).string(), options);
}

TEST(SceneLoader, LoadsTheSpring2023Scenes) {
    if (!fs::is_directory(kCourseScenes)) GTEST_SKIP() << "no course scenes at " << kCourseScenes;
    // Flat colours and PNG billboards, all images present.
    for (const char* name : {"testScene.v1_e038c70_2022-02-20.json", "testScene.v2_c4c2221_2022-02-20.json",
                             "testScene_grads.json", "testSceneUndergrad.json"}) {
        SCOPED_TRACE(name);
        const Scene scene = load_course_scene(std::string("spring2023-a03/") + name);
        EXPECT_EQ(scene.spheres.size(), 5u);
        ASSERT_EQ(scene.billboards.size(), 3u);
        EXPECT_EQ(scene.width, 600);
        EXPECT_EQ(scene.height, 600);
        EXPECT_FALSE(scene.lit());
        for (const Billboard& billboard : scene.billboards) EXPECT_NE(billboard.image, nullptr);
        EXPECT_TRUE(scene.warnings.empty()) << all_warnings(scene);
    }
    const Scene grads = load_course_scene("spring2023-a03/testScene_grads.json");
    EXPECT_EQ(grads.camera_path[0].eye, Vec3(20, 0, 30));
    const Scene undergrad = load_course_scene("spring2023-a03/testSceneUndergrad.json");
    EXPECT_EQ(undergrad.camera_path[0].eye, Vec3(2, 0, 15));
    EXPECT_TRUE(undergrad.billboards[0].has_ambient);  // image and colour: the image shows
}

TEST(SceneLoader, LoadsTheFall2020Scenes) {
    if (!fs::is_directory(kCourseScenes)) GTEST_SKIP() << "no course scenes at " << kCourseScenes;
    LoadOptions placeholders;
    placeholders.placeholder_images = true;

    // chessboard.ppm and world_map.ppm were never published: placeholders stand in.
    EXPECT_THROW(load_course_scene("fall2020-a04/scenes/example1.js"), SceneError);
    const Scene example1 = load_course_scene("fall2020-a04/scenes/example1.js", placeholders);
    EXPECT_EQ(example1.camera_path[0].eye, Vec3(0, 0, 5.5));
    EXPECT_EQ(example1.width, 299);
    EXPECT_EQ(example1.max_depth, 6);
    EXPECT_TRUE(example1.lit());
    EXPECT_EQ(example1.spheres.size(), 3u);
    ASSERT_EQ(example1.billboards.size(), 6u);
    EXPECT_EQ(example1.billboards[1].image, example1.billboards[2].image);  // one chessboard
    ASSERT_NE(example1.billboards[3].image, nullptr);                        // camera.ppm, a P3 file
    EXPECT_EQ(example1.billboards[3].image->width, 234);
    EXPECT_TRUE(example1.billboards[4].is_mirror);
    EXPECT_TRUE(example1.billboards[5].is_mirror);
    EXPECT_EQ(example1.billboards[5].image, nullptr);  // a mirror's image is not read
    EXPECT_EQ(example1.warnings.size(), 3u) << all_warnings(example1);
    EXPECT_TRUE(has_warning(example1, "/billboards/0/filename: cannot read image")) << all_warnings(example1);

    const Scene example2 = load_course_scene("fall2020-a04/scenes/example2.js");
    EXPECT_EQ(example2.width, 729);
    EXPECT_TRUE(example2.only_ambient);
    EXPECT_FALSE(example2.lit());
    ASSERT_EQ(example2.billboards.size(), 5u);
    EXPECT_TRUE(example2.billboards[3].is_mirror);
    EXPECT_TRUE(example2.warnings.empty()) << all_warnings(example2);

    const Scene mickey = load_course_scene("fall2020-a04/scenes/metal_mickey.js");
    EXPECT_EQ(mickey.spheres.size(), 3u);
    EXPECT_TRUE(mickey.billboards.empty());
    EXPECT_EQ(mickey.width, 640);
    EXPECT_EQ(mickey.height, 480);
    EXPECT_EQ(mickey.max_depth, 4);
}

TEST(SceneLoader, LoadsTheSpring2025CameraPathScenes) {
    if (!fs::is_directory(kCourseScenes)) GTEST_SKIP() << "no course scenes at " << kCourseScenes;
    LoadOptions placeholders;
    placeholders.placeholder_images = true;

    // The PNGs these scenes name were never published.
    const Scene debug = load_course_scene("spring2025-hw2/MyTestSceneSingleLightTweakedForDebug.js", placeholders);
    ASSERT_EQ(debug.camera_path.size(), 2u);
    EXPECT_TRUE(debug.is_animated());
    EXPECT_EQ(debug.camera_path[0].eye, Vec3(-4.85, -0.29, 6.4));
    EXPECT_EQ(debug.camera_path[1].lookat, Vec3(0, 0, 3));
    EXPECT_EQ(debug.width, 600);
    EXPECT_EQ(debug.spheres.size(), 3u);
    EXPECT_EQ(debug.billboards.size(), 7u);
    EXPECT_TRUE(debug.lit());

    const Scene single = load_course_scene("spring2025-hw2/testSceneSingleBB.js", placeholders);
    EXPECT_FALSE(single.is_animated());
    EXPECT_EQ(single.camera_path[0].eye, Vec3(0, 0, 5));
    EXPECT_EQ(single.width, 200);
    EXPECT_TRUE(single.spheres.empty());
    ASSERT_EQ(single.billboards.size(), 1u);
    EXPECT_NE(single.billboards[0].image, nullptr);

    for (const char* name : {"testSceneSingleSphere_and_BB.js", "testSceneSingleSphere_and_BB_close.js"}) {
        SCOPED_TRACE(name);
        const Scene scene = load_course_scene(std::string("spring2025-hw2/") + name, placeholders);
        EXPECT_EQ(scene.camera_path[0].eye, Vec3(0, 0, 0));
        EXPECT_EQ(scene.spheres.size(), 3u);
        EXPECT_GE(scene.billboards.size(), 2u);
    }
}

TEST(SceneLoader, LoadsTheSpring2025WebglScene) {
    if (!fs::is_directory(kCourseScenes)) GTEST_SKIP() << "no course scenes at " << kCourseScenes;
    // It has no width or height: the command line gives them.
    EXPECT_THROW(load_course_scene("spring2025-a03-webgl/scene1.js"), SceneError);
    LoadOptions options;
    options.placeholder_images = true;
    options.width_override = 500;
    options.height_override = 500;
    const Scene scene = load_course_scene("spring2025-a03-webgl/scene1.js", options);
    EXPECT_EQ(scene.width, 500);
    ASSERT_EQ(scene.camera_path.size(), 2u);
    EXPECT_EQ(scene.camera_path[0].eye, Vec3(-1, 3.65, 20));
    EXPECT_EQ(scene.camera_path[0].lookat, Vec3(3.86, 0, 0));
    EXPECT_EQ(scene.camera_path[1].lookat, Vec3(0, 0, 0));
    EXPECT_EQ(scene.background, Vec3(1.0, 0.9, 0.9));
    ASSERT_EQ(scene.billboards.size(), 2u);
    EXPECT_FALSE(scene.billboards[0].is_mirror);
    ASSERT_NE(scene.billboards[0].image, nullptr);  // f-texture.png is there
    EXPECT_TRUE(scene.billboards[1].is_mirror);
    EXPECT_EQ(scene.clip_near, 3);
    EXPECT_EQ(scene.clip_far, 20);
    // obj1.obj was never published: a placeholder cube stands in, as for a missing image.
    EXPECT_TRUE(has_warning(scene, "/obj/filename: cannot read OBJ")) << all_warnings(scene);
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_TRUE(scene.meshes[0].placeholder);
    EXPECT_EQ(scene.triangles.size(), 12u);
    EXPECT_EQ(scene.triangles[0].corners[0], Vec3(1.5, -0.5, 7.5)) << "the cube's corner, placed at [2, 0, 8]";
    EXPECT_EQ(scene.warnings.size(), 1u) << all_warnings(scene);
}

}  // namespace
}  // namespace clr
