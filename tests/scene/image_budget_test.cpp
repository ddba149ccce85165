// The memory budget for a scene's decoded images: every image's cost is counted from its
// header before it is decoded, the sum is limited, and the image that passes the limit is
// named with its JSON location.
#include <gtest/gtest.h>

#include <stb_image_write.h>

#include <cstdint>
#include <string>
#include <vector>

#include "core/errors.h"
#include "scene/image_budget.h"
#include "support/png_header.h"
#include "support/scene_json.h"
#include "support/scoped_env.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

using testing::png_header_only;
using testing::ScopedEnv;
using testing::TempFolder;
using namespace testing::scene_json;

// A real 8-bit RGBA PNG of `side` x `side` texels.
std::string write_png(const TempFolder& folder, const std::string& name, int side) {
    const std::vector<unsigned char> rgba(static_cast<std::size_t>(side) * side * 4, 200);
    const std::string path = folder.file(name);
    EXPECT_TRUE(stbi_write_png(path.c_str(), side, side, 4, rgba.data(), side * 4));
    return path;
}

// A scene in `folder` with one billboard per image name, in order.
std::string scene_showing(const std::vector<std::string>& images) {
    Json scene = minimal_scene();
    scene["billboards"] = Json::array();
    for (const std::string& image : images) {
        Json billboard = flat_billboard();
        billboard.erase("ambient");
        billboard["filename"] = image;
        scene["billboards"].push_back(billboard);
    }
    return scene.dump();
}

LoadOptions with_limit(std::uint64_t bytes, bool placeholders = false) {
    LoadOptions options;
    options.image_memory_limit = bytes;
    options.placeholder_images = placeholders;
    return options;
}

// The SceneError that loading gives, or "" when the scene loads.
SceneError load_error(const TempFolder& folder, const std::string& text, const LoadOptions& options) {
    try {
        parse_scene(text, folder.file("scene.json"), options);
    } catch (const SceneError& error) {
        return error;
    }
    return SceneError("", "", "");
}

TEST(ImageBudget, SumOfDecodedSizesIsLimited) {
    TempFolder folder;
    write_png(folder, "a.png", 16);
    write_png(folder, "b.png", 16);
    // Each costs 16 x 16 texels x 8 bytes (two 8-bit RGBA buffers in the decoder) = 2 KiB.
    const std::string text = scene_showing({"a.png", "b.png"});
    EXPECT_EQ(load_error(folder, text, with_limit(4096)).detail(), "");
    const SceneError error = load_error(folder, text, with_limit(4095));
    EXPECT_EQ(error.location(), "/billboards/1/filename");
    EXPECT_NE(error.detail().find("b.png' (16 x 16) needs 2 KiB to decode, and the scene's images up to this one need "
                                  "4 KiB together, more than the limit of 4095 bytes"),
              std::string::npos)
        << error.detail();
    EXPECT_NE(error.detail().find("CLRENDER_IMAGE_MEMORY_MIB"), std::string::npos) << error.detail();
}

TEST(ImageBudget, SixteenBitImagesCountTheDecodersWideBufferBeforeDecoding) {
    TempFolder folder;
    folder.write("deep.png", png_header_only(16, 16, 16));
    const std::string text = scene_showing({"deep.png"});
    // 16 x 16 x 16 bytes (two RGBA buffers of 16-bit samples) = 4096 bytes; the file holds
    // no pixels, so decoding it would fail: a failure about memory means it was counted first.
    const SceneError over = load_error(folder, text, with_limit(4095));
    EXPECT_EQ(over.location(), "/billboards/0/filename");
    EXPECT_NE(over.detail().find("deep.png' (16 x 16, 16-bit) needs 4 KiB to decode, more than the limit"),
              std::string::npos)
        << over.detail();
    EXPECT_NE(load_error(folder, text, with_limit(4096)).detail().find("corrupt PNG"), std::string::npos);
}

TEST(ImageBudget, DefaultLimitRefusesThreeHuge16BitImagesWithoutDecodingAny) {
    TempFolder folder;
    for (const char* name : {"a.png", "b.png", "c.png"}) folder.write(name, png_header_only(8192, 8192, 16));
    // 1 GiB each: two fit in 2 GiB, the third does not.
    ScopedEnv unset(kImageMemoryVariable, nullptr);
    const SceneError error = load_error(folder, scene_showing({"a.png", "b.png", "c.png"}), {});
    EXPECT_EQ(error.location(), "/billboards/2/filename");
    EXPECT_NE(error.detail().find("(8192 x 8192, 16-bit) needs 1 GiB to decode, and the scene's images up to this one "
                                  "need 3 GiB together, more than the limit of 2 GiB"),
              std::string::npos)
        << error.detail();
}

TEST(ImageBudget, AnImageShownTwiceCountsOnce) {
    TempFolder folder;
    write_png(folder, "a.png", 16);
    EXPECT_EQ(load_error(folder, scene_showing({"a.png", "./a.png"}), with_limit(2048)).detail(), "");
}

TEST(ImageBudget, PpmIsDecodedInPlace) {
    TempFolder folder;
    write_ppm(folder, "a.ppm", 16, 16);  // 16 x 16 x 4 bytes: no buffer besides the result
    EXPECT_EQ(load_error(folder, scene_showing({"a.ppm"}), with_limit(1024)).detail(), "");
    EXPECT_EQ(load_error(folder, scene_showing({"a.ppm"}), with_limit(1023)).location(), "/billboards/0/filename");
}

TEST(ImageBudget, ReportedImageIsTheFirstInTheScenesOrder) {
    TempFolder folder;
    std::vector<std::string> names;
    for (int i = 0; i < 12; ++i) {
        names.push_back("image" + std::to_string(i) + ".png");
        write_png(folder, names.back(), 16);
    }
    for (int run = 0; run < 5; ++run)
        EXPECT_EQ(load_error(folder, scene_showing(names), with_limit(5 * 2048 - 1)).location(), "/billboards/4/filename");
}

TEST(ImageBudget, PlaceholdersDoNotLiftTheLimit) {
    TempFolder folder;
    write_png(folder, "a.png", 16);
    EXPECT_EQ(load_error(folder, scene_showing({"a.png"}), with_limit(100, true)).location(), "/billboards/0/filename");
}

TEST(ImageBudget, LimitFromTheEnvironment) {
    {
        ScopedEnv unset(kImageMemoryVariable, nullptr);
        EXPECT_EQ(image_memory_limit_from_environment(), std::uint64_t(2) << 30);
    }
    {
        ScopedEnv set(kImageMemoryVariable, "5");
        EXPECT_EQ(image_memory_limit_from_environment(), std::uint64_t(5) << 20);
    }
    for (const char* bad : {"0", "abc", "-1", "1.5", "99999999999999"}) {
        ScopedEnv set(kImageMemoryVariable, bad);
        EXPECT_THROW(image_memory_limit_from_environment(), UsageError) << bad;
    }
}

}  // namespace
}  // namespace clr
