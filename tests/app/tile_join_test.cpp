// --join through the real binary (docs/command-line.md, Joining tiles): tiles rendered by
// separate processes with --crop, joined, are byte for byte the file one process writes (the
// independent expectation: that one-process render), whatever the tiles' shapes and order,
// with --size, --spp, -D, --seed, one frame of an animation, --alpha and PPM; and joining needs
// no OpenCL device. The refusals are in the bad-input catalogue.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/pixel_rect.h"
#include "support/command.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::run_clrender;
using testing::TempFolder;

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

// Renders each rectangle as a tile "tile_N.png" with `options` (N in the given order); returns
// the --join arguments, last tile first, so that the order of the tiles is not the frame's.
std::string render_tiles(const TempFolder& folder, const std::string& scene, const std::string& options,
                         const std::vector<PixelRect>& tiles) {
    std::string join;
    for (std::size_t i = 0; i < tiles.size(); ++i) {
        const std::string name = "tile_" + std::to_string(i) + ".png";
        auto result = run_clrender(scene + " -q " + options + " --crop " + format_pixel_rect(tiles[i]) + " -o " + name,
                                   folder.path());
        EXPECT_EQ(result.exit_code, 0) << result.output;
        join = " --join " + name + join;
    }
    return join;
}

// Joins the tiles into `joined` (tiles before the scene on the command line) and expects the
// bytes of `expected`, which one process rendered with the same options.
void expect_join_is_render(const TempFolder& folder, const std::string& scene, const std::string& options,
                           const std::vector<PixelRect>& tiles, const std::string& output_option,
                           const std::string& joined, const std::string& expected) {
    const std::string join = render_tiles(folder, scene, options, tiles);
    auto result = run_clrender(join.substr(1) + " " + scene + " -q " + options + output_option, folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const std::string bytes = read_bytes(folder.file(joined));
    ASSERT_FALSE(bytes.empty()) << joined;
    EXPECT_TRUE(bytes == read_bytes(folder.file(expected))) << joined << " differs from " << expected;
}

TEST(TileJoin, TwoRowBandsAreTheOneProcessRendersBytes) {
    TempFolder folder;
    write_scene(folder, "scene.json", kScene);
    ASSERT_EQ(run_clrender("scene.json -q --spp 4 -o full.png", folder.path()).exit_code, 0);
    expect_join_is_render(folder, "scene.json", "--spp 4", {{0, 83, 0, 26}, {0, 83, 26, 51}}, " -o joined.png",
                          "joined.png", "full.png");
}

// No -o: the join writes the still's default name, as the render does.
TEST(TileJoin, ThreeUnevenBlocksWithSizeSamplesAndDefines) {
    TempFolder folder;
    write_scene(folder, "scene.json", kScene);
    const std::string options = "--size 97x61 --spp 3 -D MaxDepth=2";
    ASSERT_EQ(run_clrender("scene.json -q " + options + " -o full.png", folder.path()).exit_code, 0);
    expect_join_is_render(folder, "scene.json", options, {{0, 40, 0, 17}, {40, 97, 0, 17}, {0, 97, 17, 61}}, "",
                          "scene.png", "full.png");
}

TEST(TileJoin, SevenTilesOfMixedShapes) {
    TempFolder folder;
    write_scene(folder, "scene.json", kScene);
    ASSERT_EQ(run_clrender("scene.json -q --spp 2 --seed 7 -o full.png", folder.path()).exit_code, 0);
    const std::vector<PixelRect> tiles = {{0, 30, 0, 10},   {30, 83, 0, 10},  {0, 10, 10, 51},  {10, 50, 10, 30},
                                          {50, 83, 10, 30}, {10, 83, 30, 31}, {10, 83, 31, 51}};
    expect_join_is_render(folder, "scene.json", "--spp 2 --seed 7", tiles, " -o joined.png", "joined.png", "full.png");
}

// One frame of an animation, under the default name of a --frames selection.
TEST(TileJoin, OneFrameOfAnAnimation) {
    TempFolder folder;
    write_scene(folder, "anim.json", kAnimation);
    ASSERT_EQ(run_clrender("anim.json -q --frames 2 -o full.png", folder.path()).exit_code, 0);
    expect_join_is_render(folder, "anim.json", "--frames 2", {{0, 50, 0, 51}, {50, 83, 0, 51}}, "", "anim_0002.png",
                          "full.png");
}

TEST(TileJoin, AlphaTilesMakeTheAlphaImage) {
    TempFolder folder;
    write_scene(folder, "scene.json", kScene);
    ASSERT_EQ(run_clrender("scene.json -q --alpha --spp 4 -o full.png", folder.path()).exit_code, 0);
    expect_join_is_render(folder, "scene.json", "--alpha --spp 4", {{0, 83, 0, 20}, {0, 83, 20, 51}}, " -o joined.png",
                          "joined.png", "full.png");
    // The same tiles without --alpha would lose their alpha channel: refused.
    auto result = run_clrender("scene.json -q --spp 4 --join tile_0.png --join tile_1.png -o opaque.png", folder.path());
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("tile_0.png: the tile has an alpha channel (rendered with --alpha)"), std::string::npos)
        << result.output;
    EXPECT_FALSE(fs::exists(folder.file("opaque.png")));
}

TEST(TileJoin, PpmOutputIsTheRendersPpm) {
    TempFolder folder;
    write_scene(folder, "scene.json", kScene);
    ASSERT_EQ(run_clrender("scene.json -q --spp 2 -o full.ppm", folder.path()).exit_code, 0);
    expect_join_is_render(folder, "scene.json", "--spp 2", {{0, 41, 0, 51}, {41, 83, 0, 51}}, " -o joined.ppm",
                          "joined.ppm", "full.ppm");
}

// Nothing renders: a device that does not exist does not matter, and none is named.
TEST(TileJoin, NeedsNoDevice) {
    TempFolder folder;
    write_scene(folder, "scene.json", kScene);
    const std::string join = render_tiles(folder, "scene.json", "", {{0, 83, 0, 30}, {0, 83, 30, 51}});
    auto render = run_clrender("scene.json -q -d no-such-device -o rendered.png", folder.path());
    ASSERT_EQ(render.exit_code, 3) << "a render needs the device: " << render.output;
    auto result = run_clrender("scene.json -d no-such-device --stats stats.json -o joined.png" + join, folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_EQ(result.output.find("clrender: device"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("clrender: wrote joined.png (joined from 2 tiles)"), std::string::npos) << result.output;
    EXPECT_NE(read_bytes(folder.file("stats.json")).find("\"device\": \"none (joining tiles)\""), std::string::npos);
}

}  // namespace
}  // namespace clr
