// The description a PNG carries: an sRGB chunk with the perceptual intent, and the caller's
// text as tEXt chunks, read back with libpng; the pixels are the same with or without it, and
// PPM files have no place for it.
#include <gtest/gtest.h>
#include <png.h>
#include <stb_image.h>

#include <cstdint>
#include <string>
#include <vector>

#include "output/image_writer.h"
#include "support/png_chunks.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

using testing::read_bytes;
using testing::read_png_description;
using testing::TempFolder;

Image gradient(int width, int height) {
    Image image;
    image.width = width;
    image.height = height;
    for (int i = 0; i < width * height; ++i)
        image.rgba.insert(image.rgba.end(), {std::uint8_t(i * 7), std::uint8_t(255 - i), std::uint8_t(i * 13), 255});
    return image;
}

std::vector<std::uint8_t> decoded_rgb(const std::string& path) {
    int width = 0, height = 0, channels = 0;
    stbi_uc* pixels = stbi_load(path.c_str(), &width, &height, &channels, 3);
    if (!pixels) return {};
    std::vector<std::uint8_t> rgb(pixels, pixels + width * height * 3);
    stbi_image_free(pixels);
    return rgb;
}

TEST(PngMetadata, EveryPngIsMarkedAsSrgbWithThePerceptualIntent) {
    TempFolder folder;
    write_image(folder.file("plain.png"), gradient(5, 4));
    const testing::PngDescription description = read_png_description(folder.file("plain.png"));
    ASSERT_TRUE(description.readable);
    ASSERT_TRUE(description.srgb_intent.has_value()) << "no sRGB chunk";
    EXPECT_EQ(*description.srgb_intent, PNG_sRGB_INTENT_PERCEPTUAL);
    EXPECT_TRUE(description.text.empty());
}

TEST(PngMetadata, TextIsStoredInOrderAndReadsBack) {
    TempFolder folder;
    write_image(folder.file("described.png"), gradient(5, 4), {{"Software", "clrender 9.9"}, {"Frame", "7"}});
    const testing::PngDescription description = read_png_description(folder.file("described.png"));
    ASSERT_TRUE(description.readable);
    EXPECT_EQ(description.text, (std::map<std::string, std::string>{{"Software", "clrender 9.9"}, {"Frame", "7"}}));
    const std::string bytes = read_bytes(folder.file("described.png"));
    EXPECT_NE(bytes.find(std::string("tEXtSoftware\0clrender 9.9", 25)), std::string::npos) << "a tEXt chunk";
    EXPECT_LT(bytes.find("tEXtSoftware"), bytes.find("tEXtFrame")) << "in the order given";
}

// tEXt is Latin-1 without NUL: a UTF-8 file name or a control character is written as \xNN.
TEST(PngMetadata, BytesOutsidePrintableAsciiAreEscaped) {
    TempFolder folder;
    write_image(folder.file("escaped.png"), gradient(3, 3), {{"Scene", "sc\xC3\xA8ne\n\\.json"}});
    testing::PngDescription description = read_png_description(folder.file("escaped.png"));
    ASSERT_TRUE(description.readable);
    EXPECT_EQ(description.text["Scene"], "sc\\xC3\\xA8ne\\x0A\\x5C.json");
}

TEST(PngMetadata, PixelsAreTheSameWithOrWithoutText) {
    TempFolder folder;
    const Image image = gradient(17, 9);
    write_image(folder.file("plain.png"), image);
    write_image(folder.file("described.png"), image, {{"Frame", "3"}});
    EXPECT_NE(read_bytes(folder.file("plain.png")), read_bytes(folder.file("described.png")));
    const std::vector<std::uint8_t> plain = decoded_rgb(folder.file("plain.png"));
    EXPECT_EQ(plain.size(), 17u * 9u * 3u);
    EXPECT_EQ(plain, decoded_rgb(folder.file("described.png")));
}

TEST(PngMetadata, PpmIsUnchangedByText) {
    TempFolder folder;
    const Image image = gradient(4, 2);
    write_image(folder.file("plain.ppm"), image);
    write_image(folder.file("described.ppm"), image, {{"Frame", "3"}});
    EXPECT_EQ(read_bytes(folder.file("plain.ppm")), read_bytes(folder.file("described.ppm")));
}

}  // namespace
}  // namespace clr
