// The impostor keys under "clrender" (docs/scene-format.md, Impostors): what is read, what is
// shared, and each error and warning with its JSON location.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/scene_json.h"

namespace clr {
namespace {

using testing::TempFolder;
using namespace testing::scene_json;

Json flat_impostor() { return Json::parse(R"({"center": [1, 2, 3], "width": 2, "height": 4, "ambient": [1, 0, 0]})"); }

Json with_impostors(const std::vector<Json>& impostors, const Json& view_sets = nullptr) {
    Json json = minimal_scene();
    json["clrender"]["impostors"] = impostors;
    if (!view_sets.is_null()) json["clrender"]["view_sets"] = view_sets;
    return json;
}

TEST(ImpostorLoader, ReadsAFlatImpostorWithDefaults) {
    const Scene scene = parse(with_impostors({flat_impostor()}));
    ASSERT_EQ(scene.impostors.size(), 1u);
    const Impostor& impostor = scene.impostors[0];
    EXPECT_EQ(impostor.center, Vec3(1, 2, 3));
    EXPECT_EQ(impostor.width, 2);
    EXPECT_EQ(impostor.height, 4);
    EXPECT_EQ(impostor.facing, Facing::Upright);
    EXPECT_TRUE(impostor.views.empty());
    EXPECT_EQ(impostor.ambient, Vec3(1, 0, 0));
    EXPECT_TRUE(scene.billboards.empty()) << "impostors are not course billboards";
    EXPECT_TRUE(scene.warnings.empty()) << all_warnings(scene);
}

TEST(ImpostorLoader, ReadsFacing) {
    Json free = flat_impostor();
    free["facing"] = "free";
    Json upright = flat_impostor();
    upright["facing"] = "upright";
    const Scene scene = parse(with_impostors({free, upright}));
    EXPECT_EQ(scene.impostors[0].facing, Facing::Free);
    EXPECT_EQ(scene.impostors[1].facing, Facing::Upright);
    free["facing"] = "sideways";
    EXPECT_TRUE(FailsAt(with_impostors({flat_impostor(), free}), "/clrender/impostors/1/facing",
                        "facing must be \"upright\" or \"free\""));
}

TEST(ImpostorLoader, ViewsAreReadWithUnitDirectionsAndTheirImages) {
    TempFolder folder;
    write_ppm(folder, "front.ppm", 2, 1);
    write_ppm(folder, "side.ppm", 3, 1);
    Json impostor = flat_impostor();
    impostor.erase("ambient");
    impostor["views"] = Json::parse(R"([{"filename": "front.ppm", "direction": [0, 0, 5]},
                                        {"filename": "side.ppm", "direction": [3, 0, 4]}])");
    const Scene scene = parse_scene(with_impostors({impostor}).dump(), folder.file("scene.json"));
    const Impostor& read = scene.impostors[0];
    ASSERT_EQ(read.views.size(), 2u);
    EXPECT_EQ(read.views[0].direction, Vec3(0, 0, 1));
    EXPECT_NEAR(read.views[1].direction.x, 0.6, 1e-15);
    EXPECT_NEAR(read.views[1].direction.z, 0.8, 1e-15);
    ASSERT_NE(read.views[0].image, nullptr);
    ASSERT_NE(read.views[1].image, nullptr);
    EXPECT_EQ(read.views[0].image->width, 2);
    EXPECT_EQ(read.views[1].image->width, 3);
}

TEST(ImpostorLoader, OneFilenameIsASingleView) {
    TempFolder folder;
    write_ppm(folder, "mountain.ppm", 4, 2);
    Json impostor = flat_impostor();
    impostor["filename"] = "mountain.ppm";
    const Scene scene = parse_scene(with_impostors({impostor}).dump(), folder.file("scene.json"));
    ASSERT_EQ(scene.impostors[0].views.size(), 1u);
    ASSERT_NE(scene.impostors[0].views[0].image, nullptr);
    EXPECT_EQ(scene.impostors[0].views[0].image->width, 4);
}

TEST(ImpostorLoader, ImpostorsShareAViewSetAndItsImages) {
    TempFolder folder;
    write_ppm(folder, "a.ppm", 1, 1);
    write_ppm(folder, "b.ppm", 1, 1);
    Json tree = flat_impostor();
    tree.erase("ambient");
    tree["views"] = "pine";
    Json sets = Json::parse(R"({"pine": [{"filename": "a.ppm", "direction": [1, 0, 0]},
                                         {"filename": "b.ppm", "direction": [-1, 0, 0]}]})");
    const Scene scene = parse_scene(with_impostors({tree, tree, tree}, sets).dump(), folder.file("scene.json"));
    ASSERT_EQ(scene.impostors.size(), 3u);
    for (const Impostor& impostor : scene.impostors) {
        ASSERT_EQ(impostor.views.size(), 2u);
        EXPECT_EQ(impostor.views[0].image, scene.impostors[0].views[0].image) << "one image, shared";
        EXPECT_EQ(impostor.views[1].image, scene.impostors[0].views[1].image);
        EXPECT_EQ(impostor.views[1].direction, Vec3(-1, 0, 0));
    }
    EXPECT_NE(scene.impostors[0].views[0].image, scene.impostors[0].views[1].image);
}

TEST(ImpostorLoader, UnusedViewSetsAreWarnedAboutAndNotRead) {
    Json sets = Json::parse(R"({"unused": [{"filename": "missing.png", "direction": [1, 0, 0]}]})");
    const Scene scene = parse(with_impostors({flat_impostor()}, sets));
    EXPECT_TRUE(has_warning(scene, "/clrender: view set 'unused' is not used by any impostor")) << all_warnings(scene);
}

TEST(ImpostorLoader, MissingImagesAreErrorsWhereTheFilenameIs) {
    Json tree = flat_impostor();
    tree["views"] = "pine";
    Json sets = Json::parse(R"({"pine": [{"filename": "nowhere.png", "direction": [1, 0, 0]}]})");
    EXPECT_TRUE(FailsAt(with_impostors({tree}, sets), "/clrender/view_sets/pine/0/filename", "cannot read image"));
    Json single = flat_impostor();
    single["filename"] = "nowhere.png";
    EXPECT_TRUE(FailsAt(with_impostors({flat_impostor(), single}), "/clrender/impostors/1/filename", "cannot read image"));
}

TEST(ImpostorLoader, RejectsMissingOrBadGeometry) {
    for (const char* key : {"center", "width", "height"}) {
        Json impostor = flat_impostor();
        impostor.erase(key);
        EXPECT_TRUE(FailsAt(with_impostors({impostor}), "/clrender/impostors/0", key)) << key;
    }
    for (const char* key : {"width", "height"}) {
        for (double bad : {0.0, -1.0}) {
            Json impostor = flat_impostor();
            impostor[key] = bad;
            EXPECT_TRUE(FailsAt(with_impostors({impostor}), std::string("/clrender/impostors/0/") + key, "must be > 0"));
        }
    }
}

TEST(ImpostorLoader, RejectsBadViews) {
    Json impostor = flat_impostor();
    impostor["views"] = Json::array();
    EXPECT_TRUE(FailsAt(with_impostors({impostor}), "/clrender/impostors/0/views", "at least one view"));
    impostor["views"] = Json::parse(R"([{"filename": "a.png", "direction": [0, 0, 0]}])");
    EXPECT_TRUE(FailsAt(with_impostors({impostor}), "/clrender/impostors/0/views/0/direction", "zero vector"));
    impostor["views"] = Json::parse(R"([{"direction": [0, 0, 1]}])");
    EXPECT_TRUE(FailsAt(with_impostors({impostor}), "/clrender/impostors/0/views/0", "filename"));
    impostor["views"] = Json::parse(R"([{"filename": "", "direction": [0, 0, 1]}])");
    EXPECT_TRUE(FailsAt(with_impostors({impostor}), "/clrender/impostors/0/views/0/filename", "must not be empty"));
    impostor["views"] = "oak";
    EXPECT_TRUE(FailsAt(with_impostors({impostor}), "/clrender/impostors/0/views", "no view set named \"oak\""));
    impostor["views"] = "oak";
    impostor["filename"] = "a.png";
    EXPECT_TRUE(FailsAt(with_impostors({impostor}, Json::parse(R"({"oak": [{"filename": "a.png", "direction": [1, 0, 0]}]})")),
                        "/clrender/impostors/0/filename", "either 'views' or 'filename'"));
    EXPECT_TRUE(FailsAt(with_impostors({flat_impostor()}, Json::array()), "/clrender/view_sets", "must be an object"));
}

TEST(ImpostorLoader, NeedsSomethingToShow) {
    Json impostor = flat_impostor();
    impostor.erase("ambient");
    EXPECT_TRUE(FailsAt(with_impostors({impostor}), "/clrender/impostors/0", "needs 'views'"));
}

TEST(ImpostorLoader, WarnsAboutUnknownKeysInImpostorsAndViews) {
    Json impostor = flat_impostor();
    impostor["widht"] = 3;
    impostor["IsMirror"] = 1;
    const Scene scene = parse(with_impostors({impostor}));
    EXPECT_TRUE(has_warning(scene, "/clrender/impostors/0/widht: unknown key (ignored); did you mean 'width'?"))
        << all_warnings(scene);
    EXPECT_TRUE(has_warning(scene, "/clrender/impostors/0/IsMirror: unknown key")) << all_warnings(scene);
}

TEST(ImpostorLoader, ImpostorsMustBeAList) {
    Json json = minimal_scene();
    json["clrender"]["impostors"] = flat_impostor();
    EXPECT_TRUE(FailsAt(json, "/clrender/impostors", "array"));
}

}  // namespace
}  // namespace clr
