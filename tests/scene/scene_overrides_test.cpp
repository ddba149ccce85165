// Scene values set on the command line (-D): how keys and values are read, where they go, and
// that the loader checks them as the file's own values, saying where they came from
// (docs/command-line.md, Scene overrides and checks).
#include "scene/scene_overrides.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/errors.h"
#include "scene/scene_loader.h"
#include "support/scene_json.h"

namespace clr {
namespace {

using namespace testing::scene_json;

Json applied(Json document, const std::vector<std::string>& arguments) {
    std::vector<SceneOverride> overrides;
    for (const std::string& argument : arguments) overrides.push_back(parse_scene_override(argument));
    apply_scene_overrides(document, overrides);
    return document;
}

// The UsageError message of applying `argument` to `document`, or "" when it applies.
std::string usage_error(const Json& document, const std::string& argument) {
    try {
        applied(document, {argument});
    } catch (const UsageError& error) {
        return error.what();
    }
    return "";
}

LoadOptions with_overrides(const std::vector<std::string>& arguments) {
    LoadOptions options;
    for (const std::string& argument : arguments) options.overrides.push_back(parse_scene_override(argument));
    return options;
}

TEST(SceneOverrides, DottedPathsAndJsonPointersNameTheSameValue) {
    const Json scene = {{"spheres", {{{"radius", 1}}}}, {"MaxDepth", 5}};
    EXPECT_EQ(applied(scene, {"spheres.0.radius=2"})["spheres"][0]["radius"], 2);
    EXPECT_EQ(applied(scene, {"/spheres/0/radius=3"})["spheres"][0]["radius"], 3);
    EXPECT_EQ(applied(scene, {"MaxDepth=2"})["MaxDepth"], 2);
    // RFC 6901 escapes: ~1 is '/', ~0 is '~'.
    EXPECT_EQ(applied(scene, {"/a~1b~0c=1"})["a/b~c"], 1);
}

TEST(SceneOverrides, ValuesAreJsonElseText) {
    const Json scene = Json::object();
    EXPECT_EQ(applied(scene, {"eye=[0,0,5]"})["eye"], Json({0, 0, 5}));
    EXPECT_EQ(applied(scene, {"flag=true"})["flag"], true);
    EXPECT_EQ(applied(scene, {"name=\"7\""})["name"], "7");
    EXPECT_EQ(applied(scene, {"filename=tex.png"})["filename"], "tex.png");
    EXPECT_EQ(applied(scene, {"empty="})["empty"], "");
    EXPECT_EQ(applied(scene, {"has=a=b"})["has"], "a=b");  // only the first '=' splits
}

TEST(SceneOverrides, MakesMissingObjectsOnTheWayAndAppliesInOrder) {
    const Json result = applied(Json::object(), {"clrender.spp=4", "clrender.seed=7", "clrender.spp=16"});
    EXPECT_EQ(result["clrender"], Json({{"spp", 16}, {"seed", 7}}));
}

TEST(SceneOverrides, DashAppendsToAnArray) {
    const Json result = applied(Json{{"spheres", Json::array()}}, {"spheres.-={\"radius\": 1}"});
    ASSERT_EQ(result["spheres"].size(), 1u);
    EXPECT_EQ(result["spheres"][0]["radius"], 1);
}

TEST(SceneOverrides, RefusesPathsThatLeadNowhere) {
    const Json scene = {{"spheres", {{{"radius", 1}}}}, {"MaxDepth", 5}};
    EXPECT_EQ(usage_error(scene, "spheres.3.radius=2"),
              "-D spheres.3.radius=2: /spheres has 1 element, so there is no element 3");
    EXPECT_EQ(usage_error(scene, "MaxDepth.x=2"),
              "-D MaxDepth.x=2: /MaxDepth is a number, not an object or array, so it has no 'x'");
    EXPECT_EQ(usage_error(scene, "spheres.first=2"), "-D spheres.first=2: /spheres is an array; 'first' is not an index into it");
    EXPECT_EQ(usage_error(scene, "spheres.01=2"), "-D spheres.01=2: /spheres is an array; '01' is not an index into it");
}

TEST(SceneOverrides, RefusesMalformedArguments) {
    const auto message = [](const std::string& argument) -> std::string {
        try {
            parse_scene_override(argument);
        } catch (const UsageError& error) {
            return error.what();
        }
        return "";
    };
    EXPECT_NE(message("MaxDepth").find("expected key=value"), std::string::npos);
    EXPECT_NE(message("=2").find("the key is empty"), std::string::npos);
    EXPECT_NE(message("a..b=2").find("empty part"), std::string::npos);
    EXPECT_NE(message("/a~2=1").find("'~' in a JSON pointer"), std::string::npos);
}

// A number no double holds must not become the string "[1e400,0,0]" and fail later as the
// wrong type: it is named as out of range, with its place in the scene.
TEST(SceneOverrides, ANumberTooLargeForADoubleIsOutOfRangeAtItsLocation) {
    const auto message = [](const std::string& argument) -> std::string {
        try {
            parse_scene_override(argument);
        } catch (const UsageError& error) {
            return error.what();
        }
        return "";
    };
    EXPECT_EQ(message("eye=[1e400,0,0]"),
              "-D eye=[1e400,0,0]: /eye/0: column 2: number 1e400 is out of range (numbers must be finite, at most "
              "about 1.8e308 in size)");
    EXPECT_NE(message("/spheres/0/center=[0, -1E+999, 0]").find("/spheres/0/center/1: column 5: number -1E+999 is out of range"),
              std::string::npos);
    EXPECT_NE(message("clrender.spp=1e400").find("-D clrender.spp=1e400: /clrender/spp: column 1: number 1e400 is out of range"),
              std::string::npos);
    EXPECT_NE(message("light={\"position\": [0, 2e308, 0]}").find("/light/position/1: column 18: number 2e308"),
              std::string::npos);
    // The largest double is a number.
    EXPECT_EQ(parse_scene_override("x=1.7e308").value, 1.7e308);
}

TEST(SceneOverrides, AnArrayOrObjectThatIsNotJsonIsRefusedNotTakenAsText) {
    try {
        parse_scene_override("eye=[0, 0");
        FAIL() << "taken";
    } catch (const UsageError& error) {
        EXPECT_NE(std::string(error.what()).find("-D eye=[0, 0: /eye/2: the value is not valid JSON (column 6:"),
                  std::string::npos)
            << error.what();
    }
    EXPECT_THROW(parse_scene_override("light={\"position\": }"), UsageError);
    // Other text that is not JSON stays a string, as documented.
    EXPECT_EQ(parse_scene_override("filename=3d.png").value, "3d.png");
    EXPECT_EQ(parse_scene_override("filename=\"[a].png\"").value, "[a].png");
}

// --strict counts the scene's warnings: a key repeated inside a -D value must be one of them.
TEST(SceneOverrides, ADuplicateKeyInADefinedValueIsAWarningAtItsLocation) {
    Json json = minimal_scene();
    const Scene scene = parse(json, with_overrides({"clrender={\"spp\": 4, \"spp\": 8}"}));
    EXPECT_EQ(scene.sampling.samples_per_pixel, 8) << "the last value is used, as in a file";
    ASSERT_EQ(scene.warnings.size(), 1u) << all_warnings(scene);
    EXPECT_EQ(scene.warnings[0], "/clrender/spp: duplicate key (the last value is used) (set on the command line: -D "
                                 "clrender={\"spp\": 4, \"spp\": 8})");
    json["spheres"] = Json::array();
    const Scene nested = parse(json, with_overrides({"/spheres/-={\"center\": [0,0,0], \"radius\": 1, \"radius\": 2, \"ambient\": [1,0,0]}"}));
    EXPECT_TRUE(has_warning(nested, "/spheres/-/radius: duplicate key")) << all_warnings(nested);
}

TEST(SceneOverrides, TheLoaderChecksOverriddenValuesAndNamesTheArgument) {
    Json json = minimal_scene();
    json["spheres"] = {sphere()};
    EXPECT_TRUE(FailsAt(json, "/spheres/0/radius", "radius must be > 0 (got -1) (set on the command line: -D spheres.0.radius=-1)",
                        with_overrides({"spheres.0.radius=-1"})));
    // A value the file gave keeps its plain message.
    json["spheres"][0]["radius"] = -1;
    try {
        parse(json);
        FAIL() << "no error";
    } catch (const SceneError& error) {
        EXPECT_EQ(std::string(error.detail()).find("-D"), std::string::npos) << error.detail();
    }
}

TEST(SceneOverrides, OverriddenValuesRender) {
    Json json = minimal_scene();
    json["spheres"] = {sphere()};
    const Scene scene = parse(json, with_overrides({"/spheres/0/radius=2.5", "MaxDepth=2", "DefaultColor=[0,0,1]"}));
    EXPECT_EQ(scene.spheres[0].radius, 2.5);
    EXPECT_EQ(scene.max_depth, 2);
    EXPECT_EQ(scene.background, Vec3(0, 0, 1));
    EXPECT_TRUE(scene.warnings.empty()) << all_warnings(scene);
}

TEST(SceneOverrides, AnUnknownKeyFromTheCommandLineIsWarnedAboutAsSuch) {
    const Scene scene = parse(minimal_scene(), with_overrides({"MaxDpth=2"}));
    EXPECT_TRUE(has_warning(scene, "/MaxDpth: unknown key (ignored); did you mean 'MaxDepth'? (set on the command line: -D MaxDpth=2)"))
        << all_warnings(scene);
}

TEST(SceneOverrides, CommandLineSizeSppAndSeedWinOverDefines) {
    LoadOptions options = with_overrides({"width=100", "clrender.spp=8", "clrender.seed=3"});
    options.width_override = 20;
    options.samples_override = 2;
    options.seed_override = 9u;
    const Scene scene = parse(minimal_scene(), options);
    EXPECT_EQ(scene.width, 20);
    EXPECT_EQ(scene.sampling.samples_per_pixel, 2);
    EXPECT_EQ(scene.sampling.seed, 9u);
}

TEST(SceneOverrides, SeedOverrideReplacesTheScenesSeed) {
    Json json = minimal_scene();
    json["clrender"] = {{"seed", 5}};
    EXPECT_EQ(parse(json).sampling.seed, 5u);
    LoadOptions options;
    options.seed_override = 4294967295u;
    EXPECT_EQ(parse(json, options).sampling.seed, 4294967295u);
}

TEST(SceneOverrides, APathErrorNamesTheSceneFile) {
    try {
        parse_scene(minimal_scene().dump(), "my.json", with_overrides({"spheres.0.radius=1"}));
        FAIL() << "no error";
    } catch (const UsageError& error) {
        EXPECT_STREQ(error.what(), "my.json: -D spheres.0.radius=1: /spheres does not exist, so it has no element 0");
    }
}

}  // namespace
}  // namespace clr
