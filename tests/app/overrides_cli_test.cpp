// Scene overrides and checks through the real binary: -D, --seed, --strict, --check and the
// hint for a mistyped option (docs/command-line.md, Scene overrides and checks).
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>

#include "scene/image_loader.h"
#include "support/command.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::run_clrender;
using testing::TempFolder;

// A red sphere before a dark grey background.
const char* kScene = R"({
  "eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
  "width": 40, "height": 30, "DefaultColor": [0.2, 0.2, 0.2],
  "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0, 0]}]
})";

int count_of(const std::string& text, const std::string& part) {
    int count = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
    return count;
}

std::set<std::string> entries_of(const std::string& folder) {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
    return names;
}

TEST(SceneOverridesCli, DefinesChangeTheRenderedScene) {
    TempFolder folder;
    folder.write("s.json", kScene);
    ASSERT_EQ(run_clrender("s.json -q --reference -o plain.png", folder.path()).exit_code, 0);
    const auto result = run_clrender(
        "s.json -q --reference -o set.png -D DefaultColor=[0,0,1] -D /spheres/0/ambient='[0, 1, 0]' -D spheres.0.radius=0.5",
        folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const auto plain = load_image(folder.file("plain.png"));
    const auto set = load_image(folder.file("set.png"));
    EXPECT_EQ(plain->at(0, 0, 2), 51);  // 0.2 grey
    EXPECT_EQ(set->at(0, 0, 2), 255);   // blue background
    EXPECT_EQ(plain->at(20, 15, 0), 255);
    EXPECT_EQ(set->at(20, 15, 1), 255);  // a green sphere in the centre
    // Radius 0.5 instead of 1.5: a point 1 unit off the centre is background now.
    EXPECT_EQ(plain->at(26, 15, 0), 255);
    EXPECT_EQ(set->at(26, 15, 2), 255);
}

TEST(SceneOverridesCli, ADefineBeforeTheSceneTakesOneValue) {
    TempFolder folder;
    folder.write("s.json", kScene);
    ASSERT_EQ(run_clrender("s.json -q --reference -o after.png -D DefaultColor=[0,0,1]", folder.path()).exit_code, 0);
    const auto result = run_clrender("-D DefaultColor=[0,0,1] s.json -q --reference -o before.png", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_EQ(load_image(folder.file("before.png"))->rgba, load_image(folder.file("after.png"))->rgba);
}

TEST(SceneOverridesCli, AnInvalidDefinedValueIsASceneErrorThatSaysWhereItCameFrom) {
    TempFolder folder;
    folder.write("s.json", kScene);
    const auto result = run_clrender("s.json -q -D spheres.0.radius=-2", folder.path());
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("clrender: error: s.json: /spheres/0/radius: radius must be > 0 (got -2) (set on the "
                                 "command line: -D spheres.0.radius=-2)"),
              std::string::npos)
        << result.output;
    EXPECT_EQ(entries_of(folder.path()), std::set<std::string>{"s.json"});
}

TEST(SceneOverridesCli, SizeAndSppWinOverDefinesWhateverTheOrder) {
    TempFolder folder;
    folder.write("s.json", kScene);
    const auto result = run_clrender("s.json -q --reference --size 16x12 -D width=100 -D height=100 -o out.png", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const auto image = load_image(folder.file("out.png"));
    EXPECT_EQ(image->width, 16);
    EXPECT_EQ(image->height, 12);
}

TEST(SceneOverridesCli, SeedChangesTheSamplePatternAsClrenderSeedDoes) {
    TempFolder folder;
    folder.write("s.json", kScene);
    const std::string base = "s.json -q --reference --spp 4 ";
    ASSERT_EQ(run_clrender(base + "-o default.png", folder.path()).exit_code, 0);
    ASSERT_EQ(run_clrender(base + "--seed 12345 -o seed.png", folder.path()).exit_code, 0);
    ASSERT_EQ(run_clrender(base + "-D clrender.seed=12345 -o defined.png", folder.path()).exit_code, 0);
    // --seed wins over the scene's (here defined) seed.
    ASSERT_EQ(run_clrender(base + "-D clrender.seed=7 --seed 12345 -o both.png", folder.path()).exit_code, 0);
    // Pixels, not files: the PNG description's scene digest covers the -D values as given.
    const auto pixels = [&](const char* name) { return load_image(folder.file(name))->rgba; };
    const auto seeded = pixels("seed.png");
    EXPECT_NE(pixels("default.png"), seeded) << "silhouette pixels take other samples";
    EXPECT_EQ(pixels("defined.png"), seeded);
    EXPECT_EQ(pixels("both.png"), seeded);
}

TEST(SceneOverridesCli, StrictTurnsWarningsIntoOneErrorAndWritesNothing) {
    TempFolder folder;
    // Two keys that clrender does not know: two warnings.
    folder.write("old.json", R"({"eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
                                 "width": 8, "height": 6, "shadows": 1, "antialias": 4})");
    const auto lenient = run_clrender("old.json -q --reference -o lenient.png", folder.path());
    EXPECT_EQ(lenient.exit_code, 0) << lenient.output;
    const auto strict = run_clrender("old.json -q --reference --strict -o strict.png", folder.path());
    EXPECT_EQ(strict.exit_code, 2) << strict.output;
    EXPECT_EQ(count_of(strict.output, "clrender: warning: old.json: /shadows: unknown key"), 1) << strict.output;
    EXPECT_EQ(count_of(strict.output, "clrender: warning: old.json: /antialias: unknown key"), 1) << strict.output;
    EXPECT_EQ(count_of(strict.output, "clrender: error: "), 1) << strict.output;
    EXPECT_NE(strict.output.find("clrender: error: old.json: 2 warnings (above), and --strict makes warnings errors"),
              std::string::npos)
        << strict.output;
    EXPECT_FALSE(fs::exists(folder.file("strict.png")));
    // A scene without warnings passes.
    folder.write("s.json", kScene);
    EXPECT_EQ(run_clrender("s.json -q --reference --strict -o ok.png", folder.path()).exit_code, 0);
}

TEST(SceneOverridesCli, StrictFailsOnADuplicateKeyInsideADefine) {
    TempFolder folder;
    folder.write("s.json", kScene);
    const auto strict =
        run_clrender("s.json -q --reference --strict -o strict.png -D 'clrender={\"spp\": 1, \"spp\": 2}'", folder.path());
    EXPECT_EQ(strict.exit_code, 2) << strict.output;
    EXPECT_EQ(count_of(strict.output, "clrender: warning: s.json: /clrender/spp: duplicate key"), 1) << strict.output;
    EXPECT_NE(strict.output.find("1 warning (above), and --strict makes warnings errors"), std::string::npos) << strict.output;
    EXPECT_FALSE(fs::exists(folder.file("strict.png")));
}

TEST(SceneOverridesCli, ANumberTooLargeInADefineIsOutOfRangeNotAWrongType) {
    TempFolder folder;
    folder.write("s.json", kScene);
    const auto result = run_clrender("s.json -q --reference -o out.png -D 'eye=[1e400,0,0]'", folder.path());
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_NE(result.output.find("-D eye=[1e400,0,0]: /eye/0: column 2: number 1e400 is out of range"), std::string::npos)
        << result.output;
    EXPECT_EQ(result.output.find("must be an array"), std::string::npos) << result.output;
    EXPECT_EQ(entries_of(folder.path()), std::set<std::string>{"s.json"});
}

TEST(SceneOverridesCli, CheckSummarisesWithoutAnyOpenClPlatformAndWritesNothing) {
    TempFolder folder;
    fs::create_directories(folder.file("no-icds"));
    fs::copy_file(fs::path(CLRENDER_SOURCE_DIR) / "scenes/demo/checker.png", folder.file("checker.png"));
    folder.write("s.json", R"({
      "eyeLocations": [[0, 0, 6], [1, 0, 6], [2, 0, 6]], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
      "width": 40, "height": 30, "SunLocation": [5, 5, 5], "extra": 1,
      "clrender": {"fps": 4, "frames": 10},
      "spheres": [{"center": [0, 0, 0], "radius": 1, "ambient": [1, 0, 0]},
                  {"center": [2, 0, 0], "radius": 1, "ambient": [1, 1, 1], "IsMirror": 1}],
      "billboards": [{"UpperLeft": [-1, 1, -2], "LowerLeft": [-1, -1, -2], "UpperRight": [1, 1, -2], "filename": "checker.png"},
                     {"UpperLeft": [-1, 1, -3], "LowerLeft": [-1, -1, -3], "UpperRight": [1, 1, -3], "filename": "./checker.png"}]
    })");
    const std::string no_platforms = "OCL_ICD_VENDORS=" + folder.file("no-icds");
    // The environment really hides every device: a render fails for want of one.
    EXPECT_EQ(run_clrender("s.json -q --frames 0 -o f.png", folder.path(), no_platforms).exit_code, 3);

    const std::set<std::string> before = entries_of(folder.path());
    const auto result = run_clrender("s.json --check -o 'f_%04d.png'", folder.path(), no_platforms);
    ASSERT_EQ(result.exit_code, 0) << result.output;
    for (const char* line : {"scene:      s.json\n", "size:       40 x 30, 1 sample per pixel\n",
                             "frames:     10 (2.5 s at 4 fps, 3 camera keys, linear)\n", "spheres:    2 (1 mirror)\n",
                             "billboards: 2\n", "impostors:  0\n",
                             "images:     1 file, 65536 pixels in all (1 PNG)\n",
                             "features:   spheres billboards textures alpha sun mirrors\n",
                             "warnings:   1 (on standard error, above)\n"})
        EXPECT_NE(result.output.find(line), std::string::npos) << "missing '" << line << "' in:\n" << result.output;
    EXPECT_NE(result.output.find("clrender: warning: s.json: /extra: unknown key (ignored)"), std::string::npos)
        << result.output;
    EXPECT_EQ(entries_of(folder.path()), before);
}

// The OpenCL ICD loader opens a platform's library only when platforms are listed: with an
// ICD that names a probe library, the dynamic linker's log (LD_DEBUG) shows whether the
// program looked for it.
TEST(SceneOverridesCli, CheckNeverOpensAnOpenClPlatform) {
    TempFolder folder;
    folder.write("s.json", kScene);
    fs::create_directories(folder.file("icds"));
    folder.write("icds/probe.icd", "libclrender_icd_probe.so\n");
    const std::string environment = "OCL_ICD_VENDORS=" + folder.file("icds") + " LD_DEBUG=libs";
    const auto listing = run_clrender("--list-devices", folder.path(), environment);
    EXPECT_NE(listing.output.find("libclrender_icd_probe.so"), std::string::npos) << "the probe does not work";
    const auto check = run_clrender("s.json --check", folder.path(), environment);
    EXPECT_EQ(check.exit_code, 0) << check.output;
    EXPECT_EQ(check.output.find("libclrender_icd_probe.so"), std::string::npos) << check.output;
}

TEST(SceneOverridesCli, CheckFindsSceneErrorsAndStrictWarnings) {
    TempFolder folder;
    folder.write("s.json", kScene);
    const auto bad = run_clrender("s.json --check -D spheres.0.radius=0", folder.path());
    EXPECT_EQ(bad.exit_code, 2) << bad.output;
    EXPECT_NE(bad.output.find("s.json: /spheres/0/radius: radius must be > 0"), std::string::npos) << bad.output;
    const auto strict = run_clrender("s.json --check --strict -D colour=1", folder.path());
    EXPECT_EQ(strict.exit_code, 2) << strict.output;
    EXPECT_EQ(strict.output.find("scene:"), std::string::npos) << "no summary after an error:\n" << strict.output;
}

TEST(SceneOverridesCli, CheckDecodesTheImagesAsARenderDoes) {
    TempFolder folder;
    // A PNG whose header is whole but whose pixel data is cut off: the render refuses it, and
    // --check with the same message and exit code.
    const std::string png = read_bytes(fs::path(CLRENDER_SOURCE_DIR) / "scenes/demo/backdrop.png");
    folder.write("cut.png", png.substr(0, png.size() / 2));
    folder.write("s.json", R"({"eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
      "width": 8, "height": 6, "billboards": [{"UpperLeft": [-1, 1, 0], "LowerLeft": [-1, -1, 0],
      "UpperRight": [1, 1, 0], "filename": "cut.png"}]})");
    const auto render = run_clrender("s.json -q --reference", folder.path());
    ASSERT_EQ(render.exit_code, 2) << render.output;
    const auto check = run_clrender("s.json --check", folder.path());
    EXPECT_EQ(check.exit_code, 2);
    EXPECT_EQ(check.output, render.output);
}

// Decoded, the images say whether a texel is transparent: the alpha test is listed only then.
TEST(SceneOverridesCli, CheckListsTheAlphaTestOnlyForAnImageWithTransparentTexels) {
    TempFolder folder;
    folder.write("sphere.json", kScene);
    // --alpha makes the background transparent; without it every texel is opaque, in RGBA too.
    ASSERT_EQ(run_clrender("sphere.json -q --reference --alpha -o clear.png", folder.path()).exit_code, 0);
    ASSERT_EQ(run_clrender("sphere.json -q --reference -o solid.png", folder.path()).exit_code, 0);
    for (const auto& [image, features] : {std::pair{"clear.png", "billboards textures alpha\n"},
                                          std::pair{"solid.png", "billboards textures\n"}}) {
        folder.write("s.json", std::string(R"({"eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0],
          "fov_angle": 60, "width": 8, "height": 6, "billboards": [{"UpperLeft": [-1, 1, 0],
          "LowerLeft": [-1, -1, 0], "UpperRight": [1, 1, 0], "filename": ")") + image + R"("}]})");
        const auto check = run_clrender("s.json --check", folder.path());
        EXPECT_EQ(check.exit_code, 0) << check.output;
        EXPECT_NE(check.output.find(std::string("features:   ") + features), std::string::npos) << check.output;
    }
}

// The fall 2019 format's planes and lights, and the clip depths, in --check's summary.
TEST(SceneOverridesCli, CheckListsPlanesLightsAndClipDepths) {
    TempFolder folder;
    const std::string scene = R"({"eye": [0, 2, 9], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
      "width": 8, "height": 6, "near": 1, "far": 50, "surfaces": [
        {"type": "sphere", "center": [0, 1, 0], "radius": 1, "ambient": [0.5, 0, 0], "diffuse": [0.5, 0, 0]},
        {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "ambient": [0.1, 0.1, 0.1]}],
      "lights": [{"position": [5, 5, 5], "color": [1, 1, 1]}]})";
    folder.write("lit.json", scene);
    const auto lit = run_clrender("lit.json --check", folder.path());
    EXPECT_EQ(lit.exit_code, 0) << lit.output;
    EXPECT_NE(lit.output.find("planes:     1\nlights:     1\n"), std::string::npos) << lit.output;
    EXPECT_NE(lit.output.find("features:   spheres planes lights clip\n"), std::string::npos) << lit.output;
    folder.write("flat.json", scene.substr(0, scene.size() - 1) + R"(, "OnlyAmbient": 1})");
    const auto flat = run_clrender("flat.json --check", folder.path());
    EXPECT_NE(flat.output.find("lights:     1 (off: OnlyAmbient)\n"), std::string::npos) << flat.output;
    EXPECT_NE(flat.output.find("features:   spheres planes clip\n"), std::string::npos) << flat.output;
}

TEST(SceneOverridesCli, AMistypedOptionGetsASuggestion) {
    TempFolder folder;
    folder.write("s.json", kScene);
    for (const char* typo : {"--sp 4", "--sp=4", "-spp 4", "--seeed 3", "--strikt"}) {
        const auto result = run_clrender(std::string("s.json ") + typo, folder.path());
        EXPECT_EQ(result.exit_code, 1) << typo << ": " << result.output;
        const std::string expected = std::string(typo).find("see") != std::string::npos    ? "did you mean --seed?"
                                     : std::string(typo).find("stri") != std::string::npos ? "did you mean --strict?"
                                                                                            : "did you mean --spp?";
        EXPECT_NE(result.output.find(expected), std::string::npos) << typo << ": " << result.output;
    }
    const auto far_off = run_clrender("s.json --frobnicate", folder.path());
    EXPECT_EQ(far_off.exit_code, 1);
    EXPECT_EQ(far_off.output.find("did you mean"), std::string::npos) << far_off.output;
}

// After "--" every word is a file name (a scene named -s.json): an option given there is not
// a typo of itself.
TEST(SceneOverridesCli, AnOptionAfterTheEndOfOptionsIsNamedAsSuch) {
    TempFolder folder;
    folder.write("-s.json", kScene);
    const auto scene = run_clrender("--check -- -s.json", folder.path());
    EXPECT_EQ(scene.exit_code, 0) << scene.output;
    const auto late = run_clrender("-- -s.json --check", folder.path());
    EXPECT_EQ(late.exit_code, 1) << late.output;
    EXPECT_EQ(late.output.find("did you mean"), std::string::npos) << late.output;
    EXPECT_NE(late.output.find("'--check' comes after '--', which ends the options"), std::string::npos) << late.output;
}

TEST(SceneOverridesCli, HelpAndTheCommandLineDocumentEachOption) {
    const auto help = run_clrender("--help");
    const std::string doc = read_bytes(fs::path(CLRENDER_SOURCE_DIR) / "docs/command-line.md");
    for (const char* option : {"--define", "--seed", "--strict", "--check"}) {
        EXPECT_NE(help.output.find(option), std::string::npos) << option;
        EXPECT_NE(doc.find(option), std::string::npos) << option;
    }
    EXPECT_NE(doc.find("`-D, --define KEY=VALUE`"), std::string::npos);
}

}  // namespace
}  // namespace clr
