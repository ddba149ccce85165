// The demo textures in scenes/demo are provably made by the project: regenerating them gives
// the committed bytes. And they show what the demo is for (transparent and opaque texels).
#include <gtest/gtest.h>
#include <stb_image.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "scene/image_loader.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::TempFolder;

const fs::path kDemoFolder = fs::path(CLRENDER_SOURCE_DIR) / "scenes" / "demo";
const std::set<std::string> kTextures = {"backdrop.png", "checker.png", "cutout.png", "sign.ppm"};

// Counts texels with alpha 0, alpha 255 and anything in between.
struct AlphaCounts {
    long transparent = 0, opaque = 0, partial = 0;
};

AlphaCounts count_alpha(const Image& image) {
    AlphaCounts counts;
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) {
        (image.rgba[i] == 0 ? counts.transparent : image.rgba[i] == 255 ? counts.opaque : counts.partial)++;
    }
    return counts;
}

TEST(MakeTextures, RegeneratesTheCommittedTexturesByteForByte) {
    TempFolder folder;
    const std::string command = std::string("'") + CLRENDER_MAKE_TEXTURES + "' '" + folder.path() + "'";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;

    std::set<std::string> generated;
    for (const auto& entry : fs::directory_iterator(folder.path())) generated.insert(entry.path().filename().string());
    EXPECT_EQ(generated, kTextures);
    for (const std::string& name : kTextures) {
        const std::string committed = read_bytes(kDemoFolder / name);
        ASSERT_FALSE(committed.empty()) << "scenes/demo/" << name << " is missing";
        EXPECT_TRUE(read_bytes(folder.file(name)) == committed)
            << name << " differs from scenes/demo/" << name << ": run clrender_make_textures scenes/demo";
    }
}

TEST(MakeTextures, CheckerAndCutoutHaveOnlyFullyTransparentAndOpaqueTexels) {
    for (const char* name : {"checker.png", "cutout.png"}) {
        const AlphaCounts counts = count_alpha(*load_image((kDemoFolder / name).string()));
        EXPECT_GT(counts.transparent, 0) << name;
        EXPECT_GT(counts.opaque, 0) << name;
        EXPECT_EQ(counts.partial, 0) << name;
    }
}

TEST(MakeTextures, BackdropIsOpaqueRgbAndSignIsAsciiPpm) {
    int width = 0, height = 0, channels_in_file = 0;
    ASSERT_TRUE(stbi_info((kDemoFolder / "backdrop.png").string().c_str(), &width, &height, &channels_in_file));
    EXPECT_EQ(channels_in_file, 3);
    EXPECT_EQ(read_bytes(kDemoFolder / "sign.ppm").substr(0, 5), "P3\n# ");
    const auto sign = load_image((kDemoFolder / "sign.ppm").string());
    EXPECT_FALSE(sign->has_transparency());
}

TEST(MakeTextures, DemoSceneUsesEveryTextureAndAllOfThemLoad) {
    std::ifstream in(kDemoFolder / "demo.json");
    const nlohmann::json scene = nlohmann::json::parse(in);
    std::set<std::string> used;
    for (const auto& billboard : scene.at("billboards")) used.insert(billboard.at("filename").get<std::string>());
    EXPECT_EQ(used, kTextures);
    for (const std::string& name : used) EXPECT_NO_THROW(load_image((kDemoFolder / name).string())) << name;
}

}  // namespace
}  // namespace clr
