// Where a billboard's image is read from: relative to the scene's folder, "./a.png" and "a.png"
// one file, and a name with ".." resolved as the system resolves it.
#include <gtest/gtest.h>

#include <stb_image_write.h>

#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene_loader.h"
#include "support/scene_json.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

using testing::TempFolder;
using namespace testing::scene_json;

// A 2 x 2 PNG of one colour.
void write_png(const std::string& path, unsigned char red, unsigned char blue) {
    std::vector<unsigned char> rgba(16, 255);
    for (int i = 0; i < 4; ++i) {
        rgba[4 * i] = red;
        rgba[4 * i + 1] = 0;
        rgba[4 * i + 2] = blue;
    }
    ASSERT_TRUE(stbi_write_png(path.c_str(), 2, 2, 4, rgba.data(), 8));
}

Scene scene_showing(const TempFolder& folder, const std::vector<std::string>& images) {
    Json scene = minimal_scene();
    scene["billboards"] = Json::array();
    for (const std::string& image : images) {
        Json billboard = flat_billboard();
        billboard.erase("ambient");
        billboard["filename"] = image;
        scene["billboards"].push_back(billboard);
    }
    return load_scene(folder.write("scene.json", scene.dump()), LoadOptions{});
}

// "link/../a.png" with `link` a symbolic link to other/sub: the system reads other/a.png (blue),
// not the a.png beside the scene (red) that the text would suggest.
TEST(ImagePaths, DotDotIsResolvedByTheSystemNotOnTheText) {
    TempFolder folder;
    std::filesystem::create_directories(folder.file("other/sub"));
    write_png(folder.file("a.png"), 255, 0);
    write_png(folder.file("other/a.png"), 0, 255);
    std::filesystem::create_directory_symlink("other/sub", folder.file("link"));
    const Scene scene = scene_showing(folder, {"link/../a.png", "./a.png", "a.png"});
    ASSERT_EQ(scene.billboards.size(), 3u);
    EXPECT_EQ(scene.billboards[0].image->at(0, 0, 2), 255) << "the system's other/a.png, blue";
    EXPECT_EQ(scene.billboards[0].image->at(0, 0, 0), 0);
    EXPECT_EQ(scene.billboards[1].image->at(0, 0, 0), 255) << "a.png beside the scene, red";
    EXPECT_EQ(scene.billboards[1].image.get(), scene.billboards[2].image.get()) << "./a.png and a.png: one image";
}

}  // namespace
}  // namespace clr
