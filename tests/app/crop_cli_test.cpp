// --crop through the real binary (docs/command-line.md, Crop): four crops that tile a frame,
// put together, are the full frame's bytes; each frame of an animation is cropped alike; the
// reference crops alike.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/pixel_rect.h"
#include "output/image_writer.h"
#include "scene/image_loader.h"
#include "support/command.h"
#include "support/image_rect.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::run_clrender;
using testing::TempFolder;
using testing::cut;
using testing::paste;

// Spheres (one a mirror), a textured billboard with holes, a floor, sun and shadows; 83x51, so
// that neither side is a multiple of the 16-pixel screen tiles.
const std::string kScene = R"({
  "eye": [0, 2, 12], "lookat": [0, 1, 0], "up": [0, 1, 0], "fov_angle": 60,
  "width": 83, "height": 51, "SunLocation": [20, 40, 30], "MaxDepth": 4, "DefaultColor": [0.1, 0.1, 0.2],
  "spheres": [{"center": [-2, 1, 0], "radius": 1.5, "ambient": [0.9, 0.3, 0.2], "IsMirror": 1},
              {"center": [2.5, 1, -1], "radius": 1.2, "ambient": [0.2, 0.4, 0.9]}],
  "billboards": [{"filename": "cutout.png", "UpperLeft": [-1, 4, -2], "LowerLeft": [-1, -1, -2], "UpperRight": [4, 4, -2]},
                 {"UpperLeft": [-10, -1, -10], "LowerLeft": [-10, -1, 10], "UpperRight": [10, -1, -10], "ambient": [0.5, 0.5, 0.5]}]
})";

const std::string kAnimation = R"({
  "eyeLocations": [[-3, 2, 12], [3, 3, 11]], "lookat": [0, 1, 0], "up": [0, 1, 0], "fov_angle": 60,
  "width": 83, "height": 51, "SunLocation": [20, 40, 30], "clrender": {"frames": 4},
  "spheres": [{"center": [-2, 1, 0], "radius": 1.5, "ambient": [0.9, 0.3, 0.2], "IsMirror": 1}],
  "billboards": [{"filename": "cutout.png", "UpperLeft": [-1, 4, -2], "LowerLeft": [-1, -1, -2], "UpperRight": [4, 4, -2]}]
})";

void write_scene(const TempFolder& folder, const std::string& name, const std::string& text) {
    folder.write(name, text);
    fs::copy_file(std::string(CLRENDER_SOURCE_DIR) + "/scenes/demo/cutout.png", folder.file("cutout.png"),
                  fs::copy_options::overwrite_existing);
}

TEST(CropCli, FourCropsTilingTheFrameAreTheFullFramesBytes) {
    TempFolder folder;
    write_scene(folder, "scene.json", kScene);
    auto full = run_clrender("scene.json -q --spp 4 -o full.png", folder.path());
    ASSERT_EQ(full.exit_code, 0) << full.output;
    const auto expected = load_image(folder.file("full.png"));

    Image assembled = *expected;
    std::fill(assembled.rgba.begin(), assembled.rgba.end(), 0);
    const PixelRect parts[] = {{0, 37, 0, 22}, {37, 83, 0, 22}, {0, 37, 22, 51}, {37, 83, 22, 51}};
    for (const PixelRect& rect : parts) {
        const std::string name = "crop_" + std::to_string(rect.x0) + "_" + std::to_string(rect.y0) + ".png";
        auto result = run_clrender("scene.json -q --spp 4 --crop " + format_pixel_rect(rect) + " -o " + name, folder.path());
        ASSERT_EQ(result.exit_code, 0) << result.output;
        const auto part = load_image(folder.file(name));
        ASSERT_EQ(part->width, rect.width());
        ASSERT_EQ(part->height, rect.height());
        paste(assembled, *part, rect);
    }
    // Pixels, not file bytes: each PNG's metadata names its own size.
    EXPECT_TRUE(assembled.rgba == expected->rgba) << "the crops differ from the full frame";
}

TEST(CropCli, EveryFrameOfAnAnimationIsCropped) {
    TempFolder folder;
    write_scene(folder, "anim.json", kAnimation);
    ASSERT_EQ(run_clrender("anim.json -q --frames 1,3 -o 'full_%04d.png'", folder.path()).exit_code, 0);
    const PixelRect rect{20, 61, 9, 40};
    auto result = run_clrender("anim.json -q --frames 1,3 --crop 20,61,9,40 -o 'crop_%04d.png' --video crop.mp4",
                               folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    for (const char* frame : {"0001", "0003"}) {
        const auto full = load_image(folder.file(std::string("full_") + frame + ".png"));
        const auto crop = load_image(folder.file(std::string("crop_") + frame + ".png"));
        EXPECT_TRUE(crop->rgba == cut(*full, rect).rgba) << frame;
    }
    EXPECT_TRUE(fs::exists(folder.file("crop.mp4")));
}

TEST(CropCli, TheReferenceCropsAlike) {
    TempFolder folder;
    write_scene(folder, "scene.json", kScene);
    ASSERT_EQ(run_clrender("scene.json -q --reference -o full.png", folder.path()).exit_code, 0);
    auto result = run_clrender("scene.json -q --reference --crop 30,83,17,51 -o crop.png", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const auto full = load_image(folder.file("full.png"));
    const auto crop = load_image(folder.file("crop.png"));
    EXPECT_TRUE(crop->rgba == cut(*full, PixelRect{30, 83, 17, 51}).rgba);
}

TEST(CropCli, ACropOfTheSizeOverrideIsChecked) {
    TempFolder folder;
    write_scene(folder, "scene.json", kScene);
    auto inside = run_clrender("scene.json -q --size 200x100 --crop 150,200,50,100 -o crop.png", folder.path());
    ASSERT_EQ(inside.exit_code, 0) << inside.output;
    EXPECT_EQ(load_image(folder.file("crop.png"))->width, 50);
    auto outside = run_clrender("scene.json -q --size 40x30 --crop 0,50,0,30 -o crop2.png", folder.path());
    EXPECT_EQ(outside.exit_code, 1) << outside.output;
    EXPECT_NE(outside.output.find("--crop 0,50,0,30 reaches outside the 40x30 image"), std::string::npos)
        << outside.output;
    EXPECT_FALSE(fs::exists(folder.file("crop2.png")));
}

}  // namespace
}  // namespace clr
