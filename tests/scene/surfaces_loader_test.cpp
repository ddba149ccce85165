// The fall 2019 format (scene/surfaces_loader): `surfaces` of spheres and planes with their
// Blinn-Phong materials, `lights`, their defaults and every refusal with its JSON location;
// and the course's six fall 2019 files, read without a warning.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "scene/scene_loader.h"
#include "scene/surfaces_loader.h"
#include "support/scene_json.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using namespace testing::scene_json;
using testing::TempFolder;

const fs::path kCourseScenes = fs::path(CLRENDER_SOURCE_DIR) / ".." / "shared" / "course-scenes";

Json phong_sphere() {
    return Json::parse(R"({"type": "sphere", "center": [0, 6, 0], "radius": 6, "ambient": [0.75, 0.5, 0.25],
                           "diffuse": [0.75, 0.5, 0.25], "specular": [0.75, 0.75, 0.75], "phong_exponent": 20})");
}

Json floor_plane() {
    return Json::parse(R"({"type": "plane", "point": [0, 0, 0], "normal": [0, 2, 0], "ambient": [0.125, 0.125, 0.125],
                           "diffuse": [0.5, 0.5, 0.5], "specular": [0.1, 0.1, 0.1], "phong_exponent": 0})");
}

Json fall2019_scene() {
    Json json = minimal_scene();
    json["surfaces"] = {phong_sphere(), floor_plane(), phong_sphere()};
    json["lights"] = Json::parse(R"([{"position": [30, 45, 10], "color": [0.8, 0.8, 0.8]}])");
    return json;
}

TEST(Fall2019Format, SurfacesAndLightsAreRead) {
    const Scene scene = parse(fall2019_scene());
    EXPECT_TRUE(scene.warnings.empty()) << all_warnings(scene);
    ASSERT_EQ(scene.spheres.size(), 2u);
    EXPECT_EQ(scene.spheres[0].center, Vec3(0, 6, 0));
    EXPECT_EQ(scene.spheres[0].ambient, Vec3(0.75, 0.5, 0.25));
    ASSERT_EQ(scene.planes.size(), 1u);
    EXPECT_EQ(scene.planes[0].normal, Vec3(0, 1, 0)) << "normalised";
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].position, Vec3(30, 45, 10));
    EXPECT_EQ(scene.lights[0].color, Vec3(0.8, 0.8, 0.8));
    EXPECT_TRUE(scene.lit_by_lights());
    // The two equal spheres share a material; [0] stays the default that adds nothing.
    ASSERT_EQ(scene.materials.size(), 3u);
    EXPECT_EQ(scene.spheres[0].material, scene.spheres[1].material);
    const Material& ball = scene.materials[scene.spheres[0].material];
    EXPECT_EQ(ball.diffuse, Vec3(0.75, 0.5, 0.25));
    EXPECT_EQ(ball.specular, Vec3(0.75, 0.75, 0.75));
    EXPECT_EQ(ball.phong_exponent, 20);
    EXPECT_EQ(ball.mirror, Vec3(0, 0, 0));
    EXPECT_EQ(scene.materials[0], Material{});
}

TEST(Fall2019Format, OnlyAmbientTurnsTheLightsOff) {
    Json json = fall2019_scene();
    json["OnlyAmbient"] = 1;
    EXPECT_FALSE(parse(json).lit_by_lights());
}

TEST(Fall2019Format, MaterialKeysDefaultToZeroAndMirrorIsAColour) {
    Json json = minimal_scene();
    json["surfaces"] = Json::parse(R"([{"type": "sphere", "center": [0, 0, 0], "radius": 1, "ambient": [1, 0, 0],
                                        "mirror": [0.5, 0.5, 0.5]}])");
    const Scene scene = parse(json);
    const Material& material = scene.materials[scene.spheres[0].material];
    EXPECT_EQ(material.diffuse, Vec3(0, 0, 0));
    EXPECT_EQ(material.specular, Vec3(0, 0, 0));
    EXPECT_EQ(material.phong_exponent, 0);
    EXPECT_EQ(material.mirror, Vec3(0.5, 0.5, 0.5));
    EXPECT_FALSE(scene.lit_by_lights()) << "no lights: flat colours";
}

TEST(Fall2019Format, BadSurfacesAreRefusedAtTheirLocation) {
    Json json = fall2019_scene();
    json["surfaces"][1].erase("type");
    EXPECT_TRUE(FailsAt(json, "/surfaces/1", "surface is missing required key 'type'"));
    json = fall2019_scene();
    json["surfaces"][1]["type"] = "cone";
    EXPECT_TRUE(FailsAt(json, "/surfaces/1/type",
                        "surface type must be \"sphere\", \"plane\", \"triangle\" or \"mesh\" (got \"cone\")"));
    json = fall2019_scene();
    json["surfaces"][1]["normal"] = {0, 0, 0};
    EXPECT_TRUE(FailsAt(json, "/surfaces/1/normal", "normal must be a non-zero direction"));
    json = fall2019_scene();
    json["surfaces"][1].erase("point");
    EXPECT_TRUE(FailsAt(json, "/surfaces/1", "surface is missing required key 'point'"));
    json = fall2019_scene();
    json["surfaces"][0]["radius"] = 0;
    EXPECT_TRUE(FailsAt(json, "/surfaces/0/radius", "radius must be > 0"));
    json = fall2019_scene();
    json["surfaces"][0]["phong_exponent"] = -1;
    EXPECT_TRUE(FailsAt(json, "/surfaces/0/phong_exponent", "phong_exponent must be from 0 to 1e6, got -1"));
    json = fall2019_scene();
    json["surfaces"][0]["specular"] = {0, 1e300, 0};
    EXPECT_TRUE(FailsAt(json, "/surfaces/0/specular", "each channel must be from -1e6 to 1e6, got 1e300"));
    json = fall2019_scene();
    json["surfaces"][2]["center"] = {0, 2e15, 0};
    EXPECT_TRUE(FailsAt(json, "/surfaces/2/center/1", "center[1] is 2e15, outside the range"));
    json = fall2019_scene();
    json["surfaces"][0].erase("ambient");
    EXPECT_TRUE(FailsAt(json, "/surfaces/0", "surface is missing required key 'ambient'"));
}

TEST(Fall2019Format, TrianglesAndMeshesAreMeshesWithTheirMaterial) {
    TempFolder folder;
    folder.write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
    Json json = fall2019_scene();
    json["surfaces"].push_back(Json::parse(R"({"type": "triangle", "vertices": [[0, 0, 0], [2, 0, 0], [0, 2, 0]],
                                               "ambient": [0.1, 0.2, 0.3], "diffuse": [0.5, 0.5, 0.5]})"));
    json["surfaces"].push_back(Json::parse(R"({"type": "mesh", "filename": "quad.obj", "position": [5, 0, 0], "scale": 2,
                                               "ambient": [0.3, 0.2, 0.1], "specular": [1, 1, 1], "phong_exponent": 9})"));
    const std::string path = folder.write("scene.json", json.dump());
    const Scene scene = load_scene(path);
    EXPECT_TRUE(scene.warnings.empty()) << all_warnings(scene);
    ASSERT_EQ(scene.meshes.size(), 2u);
    ASSERT_EQ(scene.triangles.size(), 3u);
    EXPECT_EQ(scene.meshes[0].ambient, Vec3(0.1, 0.2, 0.3));
    EXPECT_EQ(scene.materials[scene.meshes[0].material].diffuse, Vec3(0.5, 0.5, 0.5));
    EXPECT_EQ(scene.triangles[0].corners[1], Vec3(2, 0, 0));
    EXPECT_EQ(scene.meshes[1].ambient, Vec3(0.3, 0.2, 0.1)) << "the surface's ambient, not the .mtl's";
    EXPECT_EQ(scene.materials[scene.meshes[1].material].phong_exponent, 9);
    EXPECT_EQ(scene.triangles[1].corners[1], Vec3(7, 0, 0)) << "scaled, then placed";

    json = fall2019_scene();
    json["surfaces"][0] = Json::parse(R"({"type": "triangle", "vertices": [[0, 0, 0], [1, 1, 1], [2, 2, 2]], "ambient": [1, 1, 1]})");
    EXPECT_TRUE(FailsAt(json, "/surfaces/0/vertices", "triangle has no area: its vertices are collinear or repeated"));
    json["surfaces"][0]["vertices"] = Json::parse("[[0, 0, 0], [1e-160, 0, 0], [0, 1e-160, 0]]");
    EXPECT_TRUE(FailsAt(json, "/surfaces/0/vertices",
                        "triangle has no area: its longest edge is 1.414213562373095e-160 long, outside the range"));
    // Corners 1e-20 apart give an area in double, but below the length range the kernels'
    // weights underflow float and the triangle would vanish from their image alone.
    json["surfaces"][0]["vertices"] = Json::parse("[[0, 0, 0], [1e-20, 0, 0], [0, 1e-20, 0]]");
    EXPECT_TRUE(FailsAt(json, "/surfaces/0/vertices",
                        "triangle has no area: its longest edge is 1.414213562373095e-20 long, outside the range"));
    json["surfaces"][0]["vertices"] = Json::parse("[[0, 0, 0], [1, 0, 0]]");
    EXPECT_TRUE(FailsAt(json, "/surfaces/0/vertices", "vertices must be 3 positions"));
    json["surfaces"][0]["vertices"] = Json::parse("[[0, 0, 0], [1, 0, 0], [0, 1e16, 0]]");
    EXPECT_TRUE(FailsAt(json, "/surfaces/0/vertices/2/1", "outside the range"));
    json["surfaces"][0] = Json::parse(R"({"type": "mesh", "filename": "nowhere.obj", "ambient": [1, 1, 1]})");
    EXPECT_TRUE(FailsAt(json, "/surfaces/0/filename", "cannot read OBJ"));
}

TEST(Fall2019Format, BadLightsAreRefusedAtTheirLocation) {
    Json json = fall2019_scene();
    json["lights"][0].erase("color");
    EXPECT_TRUE(FailsAt(json, "/lights/0", "light is missing required key 'color'"));
    json = fall2019_scene();
    json["lights"][0]["position"] = {0, "up", 0};
    EXPECT_TRUE(FailsAt(json, "/lights/0/position/1", "position[1] must be a number"));
    json = fall2019_scene();
    json["SunLocation"] = {0, 10, 0};
    EXPECT_TRUE(FailsAt(json, "/lights", "'lights' (point lights with Blinn-Phong materials) and 'SunLocation'"));
    json = fall2019_scene();
    json["lights"] = Json::array();
    for (std::size_t i = 0; i <= kMaxLights; ++i) json["lights"].push_back({{"position", {0, 9, 0}}, {"color", {1, 1, 1}}});
    EXPECT_TRUE(FailsAt(json, "/lights", "a scene may have at most 256 lights, this one has 257"));
}

TEST(Fall2019Format, UnknownKeysOfSurfacesAndLightsAreWarned) {
    Json json = fall2019_scene();
    json["surfaces"][0]["shininess"] = 3;
    json["lights"][0]["intensity"] = 2;
    const Scene scene = parse(json);
    EXPECT_TRUE(has_warning(scene, "/surfaces/0/shininess")) << all_warnings(scene);
    EXPECT_TRUE(has_warning(scene, "/lights/0/intensity")) << all_warnings(scene);
}

TEST(Fall2019Format, TheCoursesFilesLoadWithoutWarnings) {
    if (!fs::is_directory(kCourseScenes)) GTEST_SKIP() << "no course scenes at " << kCourseScenes;
    int files = 0;
    for (const auto& entry : fs::directory_iterator(kCourseScenes / "fall2019-a04")) {
        SCOPED_TRACE(entry.path().string());
        const Scene scene = load_scene(entry.path().string());
        EXPECT_TRUE(scene.warnings.empty()) << all_warnings(scene);
        EXPECT_FALSE(scene.spheres.empty());
        EXPECT_FALSE(scene.lights.empty());
        EXPECT_TRUE(scene.lit_by_lights());
        ++files;
    }
    EXPECT_EQ(files, 6);
}

}  // namespace
}  // namespace clr
