// The clrender command as a user runs it: outputs, exit codes and messages (docs/command-line.md).
#include <gtest/gtest.h>

#include <filesystem>

#include "scene/image_loader.h"
#include "support/command.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::run_clrender;
using testing::TempFolder;

const char* kSmallScene = R"({
  "eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
  "width": 40, "height": 30, "DefaultColor": [0.1, 0.1, 0.1],
  "spheres": [{"type": "sphere", "center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0, 0]}],
  "billboards": [{"type": "billboard", "UpperLeft": [-8, 6, -2], "LowerLeft": [-8, -6, -2],
                  "UpperRight": [8, 6, -2], "ambient": [0, 0, 1]}]
})";

TEST(Cli, HelpDocumentsEveryOption) {
    auto result = run_clrender("--help");
    EXPECT_EQ(result.exit_code, 0);
    for (const char* option : {"--output", "--list-devices", "--device", "--size", "--reference", "--stats", "--quiet",
                               "--placeholders"})
        EXPECT_NE(result.output.find(option), std::string::npos) << option;
}

TEST(Cli, ListsDevices) {
    auto result = run_clrender("--list-devices");
    EXPECT_EQ(result.exit_code, 0);
    EXPECT_NE(result.output.find("[0] 0:0"), std::string::npos) << result.output;
}

TEST(Cli, RendersToTheDefaultNameInTheCurrentFolder) {
    TempFolder folder;
    folder.write("small.json", kSmallScene);
    auto result = run_clrender("-q small.json", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_TRUE(result.output.empty()) << "quiet means quiet: " << result.output;
    auto image = load_image(folder.file("small.png"));
    EXPECT_EQ(image->width, 40);
    EXPECT_EQ(image->height, 30);
    // Centre: the red sphere; corner: the blue billboard behind it.
    EXPECT_EQ(image->at(20, 15, 0), 255);
    EXPECT_EQ(image->at(20, 15, 2), 0);
    EXPECT_EQ(image->at(0, 0, 2), 255);
}

TEST(Cli, SizeOverrideAndPpmOutput) {
    TempFolder folder;
    folder.write("small.json", kSmallScene);
    auto result = run_clrender("small.json --size 64x48 -o out.ppm -q", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    auto image = load_image(folder.file("out.ppm"));
    EXPECT_EQ(image->width, 64);
    EXPECT_EQ(image->height, 48);
}

TEST(Cli, ReferenceRendererGivesTheSameSmallImage) {
    TempFolder folder;
    folder.write("small.json", kSmallScene);
    ASSERT_EQ(run_clrender("small.json -o kernel.png -q", folder.path()).exit_code, 0);
    ASSERT_EQ(run_clrender("small.json -o reference.png --reference -q", folder.path()).exit_code, 0);
    auto kernel = load_image(folder.file("kernel.png"));
    auto reference = load_image(folder.file("reference.png"));
    int differing = 0;
    for (std::size_t i = 0; i < kernel->rgba.size(); ++i) differing += kernel->rgba[i] != reference->rgba[i];
    EXPECT_LE(differing, 12) << "only silhouette pixels may differ";
}

TEST(Cli, StatsReportIsJsonWithTheRequiredKeys) {
    TempFolder folder;
    folder.write("small.json", kSmallScene);
    ASSERT_EQ(run_clrender("small.json -q --stats stats.json", folder.path()).exit_code, 0);
    const std::string text = read_bytes(folder.file("stats.json"));
    for (const char* key : {"\"device\"", "\"build_ms\"", "\"cache_hits\"", "\"frames\"", "\"kernel_ms\"", "\"total_ms\""})
        EXPECT_NE(text.find(key), std::string::npos) << key << " in " << text;
}

TEST(Cli, SyntaxErrorNamesFileLineAndColumnWithExitCode2) {
    TempFolder folder;
    folder.write("broken.json", "{\n  \"eye\": [0, 0, 1],\n  \"lookat\": [0, 0, 0]\n  \"up\": [0, 1, 0]\n}");
    auto result = run_clrender("broken.json", folder.path());
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.output.find("broken.json"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("line 4"), std::string::npos) << result.output;
    EXPECT_FALSE(fs::exists(folder.file("broken.png")));
}

TEST(Cli, ValidationErrorNamesTheJsonLocation) {
    TempFolder folder;
    std::string scene = kSmallScene;
    scene.replace(scene.find("\"radius\": 1.5"), 13, "\"radius\": -1");
    folder.write("bad.json", scene);
    auto result = run_clrender("bad.json", folder.path());
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.output.find("bad.json"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("/spheres/0/radius"), std::string::npos) << result.output;
}

TEST(Cli, MissingImageFailsUnlessPlaceholdersAreAsked) {
    TempFolder folder;
    std::string scene = kSmallScene;
    scene.replace(scene.find("\"ambient\": [0, 0, 1]"), 20, "\"filename\": \"nowhere.png\"");
    folder.write("image.json", scene);
    auto failed = run_clrender("image.json -q", folder.path());
    EXPECT_EQ(failed.exit_code, 2);
    EXPECT_NE(failed.output.find("/billboards/0/filename"), std::string::npos) << failed.output;
    EXPECT_NE(failed.output.find("nowhere.png"), std::string::npos) << failed.output;
    EXPECT_FALSE(fs::exists(folder.file("image.png")));
    auto placeholder = run_clrender("image.json -q --placeholders", folder.path());
    EXPECT_EQ(placeholder.exit_code, 0) << placeholder.output;
    EXPECT_TRUE(fs::exists(folder.file("image.png")));
}

TEST(Cli, MissingSceneFileIsASceneError) {
    auto result = run_clrender("/nonexistent/scene.json");
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.output.find("/nonexistent/scene.json"), std::string::npos) << result.output;
}

TEST(Cli, UnknownDeviceExitsWith3ByFlagOrEnvironment) {
    TempFolder folder;
    folder.write("small.json", kSmallScene);
    auto by_flag = run_clrender("small.json -d no-such-device-xyz", folder.path());
    EXPECT_EQ(by_flag.exit_code, 3);
    EXPECT_NE(by_flag.output.find("no-such-device-xyz"), std::string::npos) << by_flag.output;
    auto by_env = run_clrender("small.json", folder.path(), "CLRENDER_DEVICE=42");
    EXPECT_EQ(by_env.exit_code, 3);
    EXPECT_FALSE(fs::exists(folder.file("small.png")));
}

TEST(Cli, DeviceByIndexAndByName) {
    TempFolder folder;
    folder.write("small.json", kSmallScene);
    EXPECT_EQ(run_clrender("small.json -q -d 0 -o a.png", folder.path()).exit_code, 0);
    EXPECT_EQ(run_clrender("small.json -q -d 0:0 -o b.png", folder.path()).exit_code, 0);
}

TEST(Cli, UsageErrorsExitWith1) {
    TempFolder folder;
    folder.write("small.json", kSmallScene);
    EXPECT_EQ(run_clrender("", folder.path()).exit_code, 1);
    EXPECT_EQ(run_clrender("small.json -o out.bmp", folder.path()).exit_code, 1);
    EXPECT_EQ(run_clrender("small.json --size 12by3", folder.path()).exit_code, 1);
    EXPECT_EQ(run_clrender("small.json --no-such-option", folder.path()).exit_code, 1);
}

// A missing folder is made (output_folders_test.cpp); a path through a file cannot be.
TEST(Cli, UnwritableOutputExitsWith4AndLeavesNothing) {
    TempFolder folder;
    folder.write("small.json", kSmallScene);
    auto result = run_clrender("small.json -q -o small.json/new-folder/out.png", folder.path());
    EXPECT_EQ(result.exit_code, 4);
    EXPECT_NE(result.output.find("small.json/new-folder/out.png"), std::string::npos) << result.output;
    EXPECT_EQ(folder.entry_count(), 1) << "only small.json";
}

}  // namespace
}  // namespace clr

namespace clr {
namespace {

// A kernel that does not compile: the run fails with exit code 3, the build log (naming the
// kernel file and line) and the build options.
TEST(Cli, KernelBuildFailurePrintsTheLogAndOptions) {
    TempFolder folder;
    folder.write("small.json", kSmallScene);
    fs::copy(std::string(CLRENDER_SOURCE_DIR) + "/kernels", folder.file("kernels"), fs::copy_options::recursive);
    std::string source = testing::read_bytes(folder.file("kernels/shade.cl"));
    source.replace(source.find("ShadeResult result;"), 19, "ShadeResult result; this is not C;");
    folder.write("kernels/shade.cl", source);
    auto result = run_clrender("small.json -q --kernel-dir kernels", folder.path());
    EXPECT_EQ(result.exit_code, 3);
    EXPECT_NE(result.output.find("CL_BUILD_PROGRAM_FAILURE"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("kernels/shade.cl"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("-DCLR_FEATURE_SPHERES=1"), std::string::npos) << result.output;
    EXPECT_FALSE(fs::exists(folder.file("small.png")));
}

TEST(Cli, KernelDirectoryGivesTheSameImageAsTheEmbeddedKernels) {
    TempFolder folder;
    folder.write("small.json", kSmallScene);
    std::string kernels = std::string(CLRENDER_SOURCE_DIR) + "/kernels";
    ASSERT_EQ(run_clrender("small.json -q -o embedded.png", folder.path()).exit_code, 0);
    ASSERT_EQ(run_clrender("small.json -q -o from-dir.png --kernel-dir '" + kernels + "'", folder.path()).exit_code, 0);
    EXPECT_EQ(testing::read_bytes(folder.file("embedded.png")), testing::read_bytes(folder.file("from-dir.png")));
}

}  // namespace
}  // namespace clr

namespace clr {
namespace {

TEST(Cli, SamplesPerPixelSmoothEdges) {
    TempFolder folder;
    folder.write("small.json", kSmallScene);
    ASSERT_EQ(run_clrender("small.json -q -o one.png", folder.path()).exit_code, 0);
    ASSERT_EQ(run_clrender("small.json -q -o many.png --spp 16", folder.path()).exit_code, 0);
    auto one = load_image(folder.file("one.png"));
    auto many = load_image(folder.file("many.png"));
    // With one sample the red sphere's silhouette is hard: only sphere or billboard colours.
    // With 16, pixels on the silhouette mix them.
    auto mixed = [](const Image& image) {
        int count = 0;
        for (int row = 0; row < image.height; ++row)
            for (int col = 0; col < image.width; ++col) {
                int r = image.at(col, row, 0), b = image.at(col, row, 2);
                count += r > 10 && r < 245 && b > 10 && b < 245;
            }
        return count;
    };
    EXPECT_EQ(mixed(*one), 0);
    EXPECT_GT(mixed(*many), 20);
    EXPECT_EQ(run_clrender("small.json -q --spp 0", folder.path()).exit_code, 1);
    EXPECT_EQ(run_clrender("small.json -q --spp 5000", folder.path()).exit_code, 1);
}

}  // namespace
}  // namespace clr

namespace clr {
namespace {

TEST(Cli, PrecisionFloatOrDouble) {
    TempFolder folder;
    folder.write("small.json", kSmallScene);
    ASSERT_EQ(run_clrender("small.json -q -o float.png --precision float", folder.path()).exit_code, 0);
    ASSERT_EQ(run_clrender("small.json -q -o double.png --precision double", folder.path()).exit_code, 0);
    auto in_float = load_image(folder.file("float.png"));
    auto in_double = load_image(folder.file("double.png"));
    int differing = 0;
    for (std::size_t i = 0; i < in_float->rgba.size(); ++i) differing += in_float->rgba[i] != in_double->rgba[i];
    EXPECT_LE(differing, 12) << "the two precisions may differ on silhouettes only";
    EXPECT_EQ(run_clrender("small.json -q --precision half", folder.path()).exit_code, 1);
}

}  // namespace
}  // namespace clr
