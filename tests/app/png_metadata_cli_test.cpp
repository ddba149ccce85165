// The text chunks of the PNGs that clrender writes: software, scene, size, samples, seed,
// frame and that frame's camera, checked against values worked out here from the scene.
#include <gtest/gtest.h>
#include <png.h>

#include <filesystem>
#include <string>
#include <vector>
#include <nlohmann/json.hpp>

#include "support/command.h"
#include "support/png_chunks.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

using testing::read_png_description;
using testing::run_clrender;
using testing::TempFolder;

// Eleven frames: eye from (-3, 1, 8) to (3, 2, 7), lookat fixed, linear.
const char* kAnimation = R"({"eyeLocations": [[-3, 1, 8], [3, 2, 7]], "lookat": [0.5, 0, -1], "up": [0, 1, 0],
  "fov_angle": 55, "width": 16, "height": 12, "clrender": {"seed": 42},
  "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0.3, 0.2]}]})";

void expect_vector(const std::string& text, std::vector<double> expected) {
    const nlohmann::json parsed = nlohmann::json::parse(text, nullptr, false);
    ASSERT_TRUE(parsed.is_array() && parsed.size() == 3) << text;
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(parsed[i].get<double>(), expected[i], 1e-12) << text;
}

TEST(PngMetadataCli, AFrameSaysWhatItShows) {
    TempFolder folder;
    folder.write("anim.json", kAnimation);
    auto result = run_clrender("anim.json -q --frames 3 --spp 4 --size 20x10 -o 'f_%04d.png'", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    testing::PngDescription description = read_png_description(folder.file("f_0003.png"));
    ASSERT_TRUE(description.readable);
    EXPECT_EQ(description.srgb_intent, PNG_sRGB_INTENT_PERCEPTUAL);
    auto& text = description.text;
    EXPECT_EQ(text["Software"], std::string("clrender ") + CLRENDER_VERSION);
    EXPECT_EQ(text["Scene"], "anim.json");
    EXPECT_EQ(text["Size"], "20x10");
    EXPECT_EQ(text["Samples per pixel"], "4");
    EXPECT_EQ(text["Seed"], "42");
    EXPECT_EQ(text["Frame"], "3");
    expect_vector(text["Eye"], {-3 + 0.3 * 6, 1 + 0.3 * 1, 8 - 0.3 * 1});
    expect_vector(text["Lookat"], {0.5, 0, -1});
    expect_vector(text["Up"], {0, 1, 0});
    EXPECT_EQ(text["Field of view"], "55.0");
}

TEST(PngMetadataCli, AStillIsFrameZeroAndNamesTheSceneWithoutItsFolder) {
    TempFolder folder;
    std::filesystem::create_directories(folder.file("scenes"));
    folder.write("scenes/still.json", R"({"eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 0.5, 0], "fov_angle": 40,
                                         "width": 8, "height": 6})");
    auto result = run_clrender("\"$PWD/scenes/still.json\" -q -o out.png", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    testing::PngDescription description = read_png_description(folder.file("out.png"));
    ASSERT_TRUE(description.readable);
    EXPECT_EQ(description.text["Scene"], "still.json") << "no folder: the bytes do not depend on where it ran";
    EXPECT_EQ(description.text["Frame"], "0");
    EXPECT_EQ(description.text["Samples per pixel"], "1");
    expect_vector(description.text["Eye"], {0, 0, 6});
    expect_vector(description.text["Up"], {0, 0.5, 0});
}

TEST(PngMetadataCli, ACropSaysWhichRectangleOfTheFrameItIs) {
    TempFolder folder;
    folder.write("anim.json", kAnimation);
    auto result = run_clrender("anim.json -q --frames 0 --crop 2,9,1,5 -o 'c_%04d.png'", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    testing::PngDescription description = read_png_description(folder.file("c_0000.png"));
    ASSERT_TRUE(description.readable);
    EXPECT_EQ(description.text["Size"], "16x12") << "the whole frame's size";
    EXPECT_EQ(description.text["Crop"], "2,9,1,5");
}

TEST(PngMetadataCli, AFullFrameNamesNoCrop) {
    TempFolder folder;
    folder.write("anim.json", kAnimation);
    auto result = run_clrender("anim.json -q --frames 0 -o 'c_%04d.png'", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    testing::PngDescription description = read_png_description(folder.file("c_0000.png"));
    ASSERT_TRUE(description.readable);
    EXPECT_EQ(description.text.count("Crop"), 0u);
}

// The scene digest follows what decides the pixels (the scene's values, its images' bytes), not
// where the scene is: a copy elsewhere has the same digest, an edited texture another.
TEST(PngMetadataCli, TheSceneDigestChangesWithTheSceneAndItsImagesOnly) {
    TempFolder folder;
    const std::string scene = R"({"eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 40,
      "width": 8, "height": 6, "billboards": [{"UpperLeft": [-1, 1, 0], "LowerLeft": [-1, -1, 0],
      "UpperRight": [1, 1, 0], "filename": "t.ppm"}]})";
    std::filesystem::create_directories(folder.file("a"));
    std::filesystem::create_directories(folder.file("b"));
    folder.write("a/s.json", scene);
    folder.write("a/t.ppm", "P3 1 1 255 200 10 10\n");
    folder.write("b/s.json", scene);
    folder.write("b/t.ppm", "P3 1 1 255 200 10 10\n");
    auto digest = [&](const std::string& json, const std::string& png) {
        EXPECT_EQ(run_clrender(json + " -q --reference -o " + png, folder.path()).exit_code, 0);
        return read_png_description(folder.file(png)).text["Scene digest"];
    };
    const std::string first = digest("a/s.json", "a1.png");
    EXPECT_EQ(first.size(), 16u);
    EXPECT_EQ(digest("b/s.json", "b1.png"), first) << "the same scene in another folder";
    EXPECT_EQ(digest("a/s.json", "a2.png"), first) << "the same scene again";
    folder.write("b/t.ppm", "P3 1 1 255 10 200 10\n");
    EXPECT_NE(digest("b/s.json", "b2.png"), first) << "an edited texture";
    EXPECT_NE(digest("a/s.json -D DefaultColor=[0,0,1]", "a3.png"), first) << "a -D value";
}

// Pixels of another arithmetic say so, so that --resume, --join and --assemble never take them
// for the default float kernels' (the same pixels may differ in the last rounding).
TEST(PngMetadataCli, DoubleKernelsAndTheReferenceSayHowThePixelsWereComputed) {
    TempFolder folder;
    folder.write("anim.json", kAnimation);
    ASSERT_EQ(run_clrender("anim.json -q --frames 0 -o 'f_%04d.png'", folder.path()).exit_code, 0);
    ASSERT_EQ(run_clrender("anim.json -q --frames 0 --precision double -o 'd_%04d.png'", folder.path()).exit_code, 0);
    ASSERT_EQ(run_clrender("anim.json -q --frames 0 --reference -o 'r_%04d.png'", folder.path()).exit_code, 0);
    auto plain = read_png_description(folder.file("f_0000.png")).text;
    auto twice = read_png_description(folder.file("d_0000.png")).text;
    auto reference = read_png_description(folder.file("r_0000.png")).text;
    EXPECT_EQ(plain.count("Precision") + plain.count("Renderer"), 0u) << "the default names neither";
    EXPECT_EQ(twice["Precision"], "double");
    EXPECT_EQ(twice.count("Renderer"), 0u);
    EXPECT_EQ(reference["Renderer"], "host reference");
}

}  // namespace
}  // namespace clr
