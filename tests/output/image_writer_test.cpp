// Frame output: PNG and PPM round trips, alpha dropped, deterministic bytes, and failures
// that leave nothing behind.
#include "output/image_writer.h"

#include <gtest/gtest.h>
#include <stb_image.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/errors.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;

using testing::read_bytes;
using testing::TempFolder;

// 3x2 texels, every channel different, alpha varied (it must not reach the file).
Image make_test_image() {
    Image image;
    image.width = 3;
    image.height = 2;
    for (int i = 0; i < 6; ++i) {
        image.rgba.insert(image.rgba.end(), {std::uint8_t(40 * i), std::uint8_t(255 - 30 * i), std::uint8_t(7 * i + 1),
                                             std::uint8_t(i % 2 ? 0 : 200)});
    }
    return image;
}

std::vector<std::uint8_t> rgb_of(const Image& image) {
    std::vector<std::uint8_t> rgb;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        rgb.insert(rgb.end(), image.rgba.begin() + i, image.rgba.begin() + i + 3);
    }
    return rgb;
}

TEST(ImageWriter, PngDecodesToTheSameRgbWithoutAlpha) {
    TempFolder folder;
    const Image image = make_test_image();
    write_image(folder.file("frame.png"), image);

    int width = 0, height = 0, channels_in_file = 0;
    stbi_uc* pixels = stbi_load(folder.file("frame.png").c_str(), &width, &height, &channels_in_file, 3);
    ASSERT_NE(pixels, nullptr) << stbi_failure_reason();
    const std::vector<std::uint8_t> decoded(pixels, pixels + width * height * 3);
    stbi_image_free(pixels);
    EXPECT_EQ(width, 3);
    EXPECT_EQ(height, 2);
    EXPECT_EQ(channels_in_file, 3) << "outputs are opaque RGB";
    EXPECT_EQ(decoded, rgb_of(image));
}

// Noise does not compress: more than 1 MiB of deflated data, split over several IDAT chunks.
TEST(ImageWriter, LargePngSpansSeveralDataChunksAndDecodesExactly) {
    TempFolder folder;
    Image image;
    image.width = 700;
    image.height = 600;
    std::uint32_t state = 12345;
    for (int i = 0; i < image.width * image.height * 4; ++i) {
        state = state * 1664525u + 1013904223u;
        image.rgba.push_back(static_cast<std::uint8_t>(state >> 24));
    }
    write_image(folder.file("noise.png"), image);
    const std::string bytes = read_bytes(folder.file("noise.png"));
    EXPECT_GT(bytes.size(), std::size_t{1} << 20);
    int width = 0, height = 0, channels_in_file = 0;
    stbi_uc* pixels = stbi_load(folder.file("noise.png").c_str(), &width, &height, &channels_in_file, 3);
    ASSERT_NE(pixels, nullptr) << stbi_failure_reason();
    const std::vector<std::uint8_t> decoded(pixels, pixels + width * height * 3);
    stbi_image_free(pixels);
    EXPECT_EQ(width, 700);
    EXPECT_EQ(height, 600);
    EXPECT_EQ(decoded, rgb_of(image));
}

TEST(ImageWriter, PpmIsBinaryP6WithExactBytes) {
    TempFolder folder;
    const Image image = make_test_image();
    write_image(folder.file("frame.ppm"), image);
    const std::vector<std::uint8_t> rgb = rgb_of(image);
    EXPECT_EQ(read_bytes(folder.file("frame.ppm")), "P6\n3 2\n255\n" + std::string(rgb.begin(), rgb.end()));
}

TEST(ImageWriter, SameImageGivesSameBytes) {
    TempFolder folder;
    const Image image = make_test_image();
    for (const char* extension : {".png", ".ppm"}) {
        write_image(folder.file(std::string("a") + extension), image);
        write_image(folder.file(std::string("b") + extension), image);
        EXPECT_EQ(read_bytes(folder.file(std::string("a") + extension)),
                  read_bytes(folder.file(std::string("b") + extension)))
            << extension;
    }
}

TEST(ImageWriter, ReplacesAnExistingFile) {
    TempFolder folder;
    std::ofstream(folder.file("frame.ppm")) << "old contents";
    write_image(folder.file("frame.ppm"), make_test_image());
    EXPECT_EQ(read_bytes(folder.file("frame.ppm")).substr(0, 3), "P6\n");
    EXPECT_EQ(folder.entry_count(), 1);
}

TEST(ImageWriter, FormatFollowsTheExtensionInAnyCase) {
    EXPECT_EQ(image_format_for("out/frame.png"), ImageFormat::Png);
    EXPECT_EQ(image_format_for("FRAME.PNG"), ImageFormat::Png);
    EXPECT_EQ(image_format_for("frame.Ppm"), ImageFormat::Ppm);
    EXPECT_EQ(image_format_for("dotted.name.ppm"), ImageFormat::Ppm);
}

TEST(ImageWriter, UnknownExtensionIsAUsageErrorListingTheSupportedOnes) {
    for (const char* path : {"frame.jpg", "frame", "png", "frame.png.bak"}) {
        try {
            image_format_for(path);
            ADD_FAILURE() << "no UsageError for " << path;
        } catch (const UsageError& error) {
            const std::string message = error.what();
            EXPECT_NE(message.find(path), std::string::npos) << message;
            EXPECT_NE(message.find(".png, .ppm"), std::string::npos) << message;
        }
    }
    TempFolder folder;
    EXPECT_THROW(write_image(folder.file("frame.jpg"), make_test_image()), UsageError);
    EXPECT_EQ(folder.entry_count(), 0);
}

TEST(ImageWriter, UnwritablePathIsAnOutputErrorThatLeavesNothing) {
    TempFolder folder;
    const std::string path = folder.file("no_such_folder/frame.png");
    try {
        write_image(path, make_test_image());
        ADD_FAILURE() << "no OutputError";
    } catch (const OutputError& error) {
        EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
        EXPECT_EQ(error.code(), kExitOutput);
    }
    EXPECT_FALSE(fs::exists(path));
    EXPECT_EQ(folder.entry_count(), 0);
}

TEST(ImageWriter, FailedRenameLeavesNoTemporaryFile) {
    TempFolder folder;
    fs::create_directory(folder.file("taken.png"));  // a folder where the image should go
    EXPECT_THROW(write_image(folder.file("taken.png"), make_test_image()), OutputError);
    EXPECT_TRUE(fs::is_directory(folder.file("taken.png")));
    EXPECT_EQ(folder.entry_count(), 1);
}

TEST(ImageWriter, RejectsAnImageWhoseSizeDoesNotMatchItsData) {
    TempFolder folder;
    Image image = make_test_image();
    image.rgba.pop_back();
    EXPECT_THROW(write_image(folder.file("frame.png"), image), OutputError);
    EXPECT_EQ(folder.entry_count(), 0);
}

}  // namespace
}  // namespace clr
