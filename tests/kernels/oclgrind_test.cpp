// The kernels on Oclgrind, the OpenCL simulator that checks every memory access
// (docs/opencl-devices.md): a frame of textured billboards with transparent texels renders
// there without an invalid access and with the pixels of the default device. Skipped where
// Oclgrind is not installed; scripts/oclgrind.sh sweeps every feature.
#include <gtest/gtest.h>

#include <filesystem>

#include "scene/image_loader.h"
#include "support/command.h"
#include "support/image_compare.h"

namespace clr {
namespace {

using testing::run_clrender;
using testing::TempFolder;

const char* kOclgrindIcd = "/usr/lib/oclgrind/liboclgrind-rt-icd.so";

// checker.png (opaque squares) fills the frame behind cutout.png (a tree with transparent
// texels) and a sphere that shows through its holes. 37 columns: the last screen tile has
// 5 lanes.
std::string textured_scene() {
    std::string demo = std::string(CLRENDER_SOURCE_DIR) + "/scenes/demo/";
    return R"({"eye": [0, 0, 8], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 70,
      "width": 37, "height": 26, "DefaultColor": [0.1, 0.1, 0.1],
      "spheres": [{"center": [0.5, 0, -2], "radius": 2.5, "ambient": [0.9, 0.2, 0.2]}],
      "billboards": [
        {"UpperLeft": [-9, 7, -4], "LowerLeft": [-9, -7, -4], "UpperRight": [9, 7, -4], "filename": ")" +
           demo + R"(checker.png"},
        {"UpperLeft": [-3, 3, 1], "LowerLeft": [-3, -3, 1], "UpperRight": [3, 3, 1], "filename": ")" + demo +
           R"(cutout.png"}]})";
}

TEST(Oclgrind, TexturedFrameReadsOnlyItsTexelsAndMatchesTheDefaultDevice) {
    if (!std::filesystem::exists(kOclgrindIcd)) GTEST_SKIP() << "Oclgrind is not installed";
    TempFolder folder;
    folder.write("scene.json", textured_scene());
    // The ICD loader reads its vendor list from OCL_ICD_VENDORS: Oclgrind's alone, nothing
    // under /etc changes. The program cache is off so that Oclgrind compiles the kernels.
    std::filesystem::create_directory(folder.file("vendors"));
    folder.write("vendors/oclgrind.icd", std::string(kOclgrindIcd) + "\n");
    std::string oclgrind = "OCL_ICD_VENDORS=" + folder.file("vendors") +
                           " CLRENDER_DEVICE=Oclgrind CLRENDER_CACHE_DIR=off OCLGRIND_CHECK_API=1";

    auto simulated = run_clrender("-q scene.json -o oclgrind.png", folder.path(), oclgrind);
    ASSERT_EQ(simulated.exit_code, 0) << simulated.output;
    // Oclgrind reports each invalid access, race or API misuse on stderr; quiet clrender
    // prints nothing else.
    EXPECT_EQ(simulated.output, "");
    auto device = run_clrender("-q scene.json -o device.png", folder.path());
    ASSERT_EQ(device.exit_code, 0) << device.output;

    auto comparison = testing::compare_images(*load_image(folder.file("oclgrind.png")),
                                              *load_image(folder.file("device.png")));
    // Rounding may move a texel or silhouette edge by a pixel, never more.
    EXPECT_EQ(comparison.differing_off_edge, 0) << comparison.first_off_edge;
    EXPECT_LT(comparison.differing_fraction(), 0.02) << comparison.differing << " pixels differ";
}

}  // namespace
}  // namespace clr
