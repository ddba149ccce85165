// Hints for the likeliest mistaken keys (docs/scene-format.md, Warnings), and images told
// apart by file rather than by name (docs/scene-format.md, Images).
#include "scene/key_hints.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "scene/scene_loader.h"
#include "support/scene_json.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::TempFolder;
using namespace testing::scene_json;

TEST(KeyHints, ClrenderKeysAtTheTopLevelPointUnderClrender) {
    Json json = minimal_scene();
    json["spp"] = 4;
    json["fps"] = 24;
    const Scene scene = parse(json);
    EXPECT_TRUE(has_warning(scene, "/spp: unknown key (ignored); 'spp' belongs under \"clrender\": \"clrender\": {\"spp\": ...}"))
        << all_warnings(scene);
    EXPECT_TRUE(has_warning(scene, "/fps: unknown key (ignored); 'fps' belongs under \"clrender\"")) << all_warnings(scene);
    EXPECT_EQ(scene.sampling.samples_per_pixel, 1) << "a hint never reads the key";
}

TEST(KeyHints, KeysSpeltTooDifferentlyForASuggestion) {
    Json json = minimal_scene();
    json["background"] = {0, 0, 1};
    json["FOV"] = 45;
    const Scene scene = parse(json);
    EXPECT_TRUE(has_warning(scene, "/background: unknown key (ignored); did you mean 'DefaultColor'?")) << all_warnings(scene);
    EXPECT_TRUE(has_warning(scene, "/FOV: unknown key (ignored); did you mean 'fov_angle'?")) << all_warnings(scene);
}

TEST(KeyHints, AMissingRequiredKeyNamesTheMistakenOne) {
    Json json = minimal_scene();
    json["fov"] = json["fov_angle"];
    json.erase("fov_angle");
    EXPECT_TRUE(FailsAt(json, "", "scene is missing required key 'fov_angle' (it has 'fov': did you mean 'fov_angle'?)"));
}

TEST(KeyHints, ABillboardWithAnImageKeyIsToldAboutFilename) {
    Json json = minimal_scene();
    Json billboard = flat_billboard();
    billboard.erase("ambient");
    billboard["texture"] = "tex.png";
    json["billboards"] = {billboard};
    EXPECT_TRUE(FailsAt(json, "/billboards/0", "(it has 'texture': did you mean 'filename'?)"));
    billboard["ambient"] = {0, 1, 0};
    json["billboards"] = {billboard};
    const Scene scene = parse(json);
    EXPECT_TRUE(has_warning(scene, "/billboards/0/texture: unknown key (ignored); did you mean 'filename'?"))
        << all_warnings(scene);
}

// A mesh is told about its keys as a sphere or billboard is: `colour` is its `ambient`, `file`
// its `filename`.
TEST(KeyHints, AMeshIsToldAboutItsKeys) {
    TempFolder folder;
    folder.write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    Json json = minimal_scene();
    json["obj"] = {{"file", "t.obj"}};
    EXPECT_TRUE(
        FailsAt(json, "/obj", "obj is missing required key 'filename' (it has 'file': did you mean 'filename'?)"));
    json["obj"] = {{"filename", "t.obj"}, {"colour", {1, 0, 0}}, {"pos", {0, 1, 0}}};
    const Scene scene = parse_scene(json.dump(), folder.file("scene.json"));
    EXPECT_TRUE(has_warning(scene, "/obj/colour: unknown key (ignored); did you mean 'ambient'?"))
        << all_warnings(scene);
    EXPECT_TRUE(has_warning(scene, "/obj/pos: unknown key (ignored); did you mean 'position'?")) << all_warnings(scene);
}

TEST(KeyHints, SpellingSuggestionsStillWork) {
    Json json = minimal_scene();
    json["spheres"] = {sphere()};
    json["spheres"][0]["radious"] = 2;
    json["spheres"][0]["colour"] = {1, 0, 0};
    const Scene scene = parse(json);
    EXPECT_TRUE(has_warning(scene, "/spheres/0/radious: unknown key (ignored); did you mean 'radius'?")) << all_warnings(scene);
    EXPECT_TRUE(has_warning(scene, "/spheres/0/colour: unknown key (ignored); did you mean 'ambient'?")) << all_warnings(scene);
}

// Two names of one file, through a symbolic link and a hard link, are one image, read once.
TEST(ImageFiles, NamesOfOneFileAreReadOnce) {
    TempFolder folder;
    write_ppm(folder, "a.ppm", 2, 1);
    fs::create_symlink("a.ppm", folder.file("link.ppm"));
    fs::create_hard_link(folder.file("a.ppm"), folder.file("hard.ppm"));
    write_ppm(folder, "b.ppm", 1, 1);
    Json json = minimal_scene();
    json["billboards"] = {flat_billboard(), flat_billboard(), flat_billboard(), flat_billboard()};
    json["billboards"][0]["filename"] = "a.ppm";
    json["billboards"][1]["filename"] = "link.ppm";
    json["billboards"][2]["filename"] = "hard.ppm";
    json["billboards"][3]["filename"] = "b.ppm";
    const Scene scene = parse_scene(json.dump(), folder.file("scene.json"));
    EXPECT_EQ(scene.billboards[0].image, scene.billboards[1].image);
    EXPECT_EQ(scene.billboards[0].image, scene.billboards[2].image);
    EXPECT_NE(scene.billboards[0].image, scene.billboards[3].image);
    ASSERT_EQ(scene.image_files.size(), 2u);
    EXPECT_EQ(scene.image_files[0].path, folder.file("a.ppm"));
    EXPECT_EQ(scene.image_files[0].format, "PPM");
    EXPECT_EQ(scene.image_files[0].width, 2);
}

TEST(ImageFiles, HeadersOnlyLeavesImagesUndecoded) {
    TempFolder folder;
    write_ppm(folder, "a.ppm", 3, 2);
    Json json = minimal_scene();
    json["billboards"] = {flat_billboard()};
    json["billboards"][0]["filename"] = "a.ppm";
    LoadOptions options;
    options.decode_images = false;
    const Scene scene = parse_scene(json.dump(), folder.file("scene.json"), options);
    EXPECT_EQ(scene.billboards[0].image, nullptr);
    ASSERT_EQ(scene.image_files.size(), 1u);
    EXPECT_EQ(scene.image_files[0].width, 3);
    EXPECT_EQ(scene.image_files[0].height, 2);
    EXPECT_FALSE(scene.image_files[0].alpha_channel);
    // A header that cannot be read is still an error, with the decoder's reason.
    folder.write("a.ppm", "P6\n3 2\n255\n\x01");
    EXPECT_TRUE(TextFailsAt(json.dump(), "/billboards/0/filename", "truncated PPM data", options, folder.file("scene.json")));
}

}  // namespace
}  // namespace clr
