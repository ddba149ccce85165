// Image input: every supported format and variant read to exact, independently known 8-bit
// RGBA texels, and every failure reported as a one-line ImageError.
#include "scene/image_loader.h"

#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using Texel = std::array<int, 4>;

using testing::read_bytes;
using testing::TempFolder;

Texel texel_at(const Image& image, int col, int row) {
    return {image.at(col, row, 0), image.at(col, row, 1), image.at(col, row, 2), image.at(col, row, 3)};
}

// Expects load_image(path) to fail with a one-line message containing `fragment`.
void expect_image_error(const std::string& path, const std::string& fragment) {
    try {
        load_image(path);
        ADD_FAILURE() << "no ImageError for " << path;
    } catch (const ImageError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find(fragment), std::string::npos) << "message: " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "message: " << message;
    }
}

bool have_ffmpeg() { return std::system("ffmpeg -version >/dev/null 2>&1") == 0; }

// Encodes raw big-endian 16-bit samples as a 16-bit PNG with the ffmpeg program (an encoder
// independent of stb), e.g. pixel_format "rgba64be".
std::string make_16bit_png(const TempFolder& folder, const std::string& pixel_format, int width, int height,
                           const std::vector<std::uint16_t>& samples) {
    std::string raw;
    for (std::uint16_t s : samples) raw += {char(s >> 8), char(s & 0xFF)};
    folder.write("in.raw", raw);
    const std::string png = folder.file(pixel_format + ".png");
    const std::string command = "ffmpeg -v error -y -f rawvideo -pix_fmt " + pixel_format + " -s " +
                                std::to_string(width) + "x" + std::to_string(height) + " -i '" +
                                folder.file("in.raw") + "' -frames:v 1 '" + png + "'";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    // IHDR's bit depth is byte 24 of the file: make sure the test really reads 16 bits.
    EXPECT_EQ(read_bytes(png).at(24), 16) << "ffmpeg did not write a 16-bit PNG";
    return png;
}

// ---------------------------------------------------------------------------------------
// PNG and JPEG

TEST(ImageLoader, ReadsRgbPngWithOpaqueAlpha) {
    TempFolder folder;
    const std::uint8_t rgb[] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 10, 20, 30};  // 2x2
    ASSERT_TRUE(stbi_write_png(folder.file("rgb.png").c_str(), 2, 2, 3, rgb, 6));
    const auto image = load_image(folder.file("rgb.png"));
    ASSERT_EQ(image->width, 2);
    ASSERT_EQ(image->height, 2);
    EXPECT_EQ(texel_at(*image, 0, 0), (Texel{255, 0, 0, 255}));
    EXPECT_EQ(texel_at(*image, 1, 0), (Texel{0, 255, 0, 255}));
    EXPECT_EQ(texel_at(*image, 0, 1), (Texel{0, 0, 255, 255}));
    EXPECT_EQ(texel_at(*image, 1, 1), (Texel{10, 20, 30, 255}));
    EXPECT_EQ(image->path, folder.file("rgb.png"));
    EXPECT_FALSE(image->has_transparency());
}

TEST(ImageLoader, ReadsRgbaPngKeepingAlpha) {
    TempFolder folder;
    const std::uint8_t rgba[] = {1, 2, 3, 0, 4, 5, 6, 128, 7, 8, 9, 255};  // 3x1
    ASSERT_TRUE(stbi_write_png(folder.file("rgba.png").c_str(), 3, 1, 4, rgba, 12));
    const auto image = load_image(folder.file("rgba.png"));
    ASSERT_EQ(image->width, 3);
    ASSERT_EQ(image->height, 1);
    EXPECT_EQ(texel_at(*image, 0, 0), (Texel{1, 2, 3, 0}));
    EXPECT_EQ(texel_at(*image, 1, 0), (Texel{4, 5, 6, 128}));
    EXPECT_EQ(texel_at(*image, 2, 0), (Texel{7, 8, 9, 255}));
    EXPECT_TRUE(image->has_transparency());
}

TEST(ImageLoader, ReadsGreyPngsAsGreyRgb) {
    TempFolder folder;
    const std::uint8_t grey[] = {0, 77, 200};
    const std::uint8_t grey_alpha[] = {90, 0, 180, 255};
    ASSERT_TRUE(stbi_write_png(folder.file("grey.png").c_str(), 3, 1, 1, grey, 3));
    ASSERT_TRUE(stbi_write_png(folder.file("grey_alpha.png").c_str(), 2, 1, 2, grey_alpha, 4));

    const auto image = load_image(folder.file("grey.png"));
    EXPECT_EQ(texel_at(*image, 0, 0), (Texel{0, 0, 0, 255}));
    EXPECT_EQ(texel_at(*image, 1, 0), (Texel{77, 77, 77, 255}));
    EXPECT_EQ(texel_at(*image, 2, 0), (Texel{200, 200, 200, 255}));

    const auto with_alpha = load_image(folder.file("grey_alpha.png"));
    EXPECT_EQ(texel_at(*with_alpha, 0, 0), (Texel{90, 90, 90, 0}));
    EXPECT_EQ(texel_at(*with_alpha, 1, 0), (Texel{180, 180, 180, 255}));
}

TEST(ImageLoader, Reads16BitRgbaPngRoundingToNearest) {
    if (!have_ffmpeg()) GTEST_SKIP() << "the ffmpeg program is needed to make a 16-bit PNG";
    TempFolder folder;
    // Expected bytes are round(v * 255 / 65535) = round(v / 257): 0x3333 = 51 * 257 exactly;
    // 0x01FF / 257 = 1.99 -> 2 (truncating to the high byte would give 1); 0x8000 -> 127.5 -> 128.
    const std::string png = make_16bit_png(folder, "rgba64be", 2, 1,
                                           {0x3333, 0x6666, 0x9999, 0xFFFF, 0x00FF, 0x01FF, 0xFEFF, 0x8000});
    const auto image = load_image(png);
    ASSERT_EQ(image->width, 2);
    ASSERT_EQ(image->height, 1);
    EXPECT_EQ(texel_at(*image, 0, 0), (Texel{0x33, 0x66, 0x99, 255}));
    EXPECT_EQ(texel_at(*image, 1, 0), (Texel{1, 2, 254, 128}));
}

TEST(ImageLoader, Reads16BitGreyPngs) {
    if (!have_ffmpeg()) GTEST_SKIP() << "the ffmpeg program is needed to make a 16-bit PNG";
    TempFolder folder;
    const auto grey = load_image(make_16bit_png(folder, "gray16be", 2, 1, {0x0000, 0xA0A0}));
    EXPECT_EQ(texel_at(*grey, 0, 0), (Texel{0, 0, 0, 255}));
    EXPECT_EQ(texel_at(*grey, 1, 0), (Texel{0xA0, 0xA0, 0xA0, 255}));
    const auto grey_alpha = load_image(make_16bit_png(folder, "ya16be", 1, 1, {0x1414, 0x0000}));
    EXPECT_EQ(texel_at(*grey_alpha, 0, 0), (Texel{0x14, 0x14, 0x14, 0}));
}

TEST(ImageLoader, ReadsJpegAsOpaqueRgb) {
    TempFolder folder;
    // JPEG is lossy, but a uniform 16x16 block at quality 100 comes back within a step or two.
    std::vector<std::uint8_t> rgb;
    for (int i = 0; i < 16 * 16; ++i) rgb.insert(rgb.end(), {200, 100, 50});
    ASSERT_TRUE(stbi_write_jpg(folder.file("photo.jpg").c_str(), 16, 16, 3, rgb.data(), 100));
    const auto image = load_image(folder.file("photo.jpg"));
    ASSERT_EQ(image->width, 16);
    ASSERT_EQ(image->height, 16);
    const Texel texel = texel_at(*image, 7, 9);
    EXPECT_NEAR(texel[0], 200, 3);
    EXPECT_NEAR(texel[1], 100, 3);
    EXPECT_NEAR(texel[2], 50, 3);
    EXPECT_EQ(texel[3], 255);
}

TEST(ImageLoader, DetectsTheFormatByContentNotByName) {
    TempFolder folder;
    const std::uint8_t rgb[] = {9, 8, 7};
    ASSERT_TRUE(stbi_write_png(folder.file("really_a_png.ppm").c_str(), 1, 1, 3, rgb, 3));
    folder.write("really_a_ppm.png", "P3 1 1 255 4 5 6\n");
    EXPECT_EQ(texel_at(*load_image(folder.file("really_a_png.ppm")), 0, 0), (Texel{9, 8, 7, 255}));
    EXPECT_EQ(texel_at(*load_image(folder.file("really_a_ppm.png")), 0, 0), (Texel{4, 5, 6, 255}));
}

// ---------------------------------------------------------------------------------------
// PPM

TEST(ImageLoader, ReadsBinaryPpmWithComments) {
    TempFolder folder;
    folder.write("p6.ppm", std::string("P6\n# made by hand\n2 1\n# maxval next\n255\n") +
                               std::string("\x00\x80\xff\x0a\x0b\x0c", 6));
    const auto image = load_image(folder.file("p6.ppm"));
    ASSERT_EQ(image->width, 2);
    ASSERT_EQ(image->height, 1);
    EXPECT_EQ(texel_at(*image, 0, 0), (Texel{0, 128, 255, 255}));
    EXPECT_EQ(texel_at(*image, 1, 0), (Texel{10, 11, 12, 255}));
}

// Netpbm: a comment may come before the one whitespace byte that ends the header; as
// libnetpbm reads it, the comment's newline is that byte, so the raster starts right after.
TEST(ImageLoader, ReadsBinaryPpmWithACommentRightAfterMaxval) {
    TempFolder folder;
    folder.write("c.ppm", std::string("P6 2 1 255#made by hand\n") + std::string("\x01\x02\x03\x0a\x0b\x0c", 6));
    const auto image = load_image(folder.file("c.ppm"));
    EXPECT_EQ(texel_at(*image, 0, 0), (Texel{1, 2, 3, 255}));
    EXPECT_EQ(texel_at(*image, 1, 0), (Texel{10, 11, 12, 255}));
    // A raster byte that is '#' right after the whitespace is data, not a comment.
    folder.write("hash.ppm", std::string("P6 1 1 255\n#\x02\x03"));
    EXPECT_EQ(texel_at(*load_image(folder.file("hash.ppm")), 0, 0), (Texel{'#', 2, 3, 255}));
    // A comment that never ends leaves no raster, and says so.
    folder.write("open.ppm", "P6 1 1 255#no end to this comment");
    expect_image_error(folder.file("open.ppm"), "truncated PPM data: the comment after maxval runs to the end of the file");
}

TEST(ImageLoader, ReadsBinaryPpmWithSixteenBitSamples) {
    TempFolder folder;
    // maxval > 255: two bytes a sample, most significant first; 0x01FF / 257 = 1.99 -> 2.
    folder.write("p6_16.ppm", std::string("P6 1 1 65535\n") + std::string("\x01\xff\xff\xff\x00\x00", 6));
    EXPECT_EQ(texel_at(*load_image(folder.file("p6_16.ppm")), 0, 0), (Texel{2, 255, 0, 255}));
}

TEST(ImageLoader, ReadsAsciiPpmWithCommentsAnywhere) {
    TempFolder folder;
    // maxval 15: a sample v becomes v * 255 / 15 = 17 v exactly.
    folder.write("p3.ppm",
                 "P3 # magic\n"
                 "# whole-line comment\n"
                 "2 # width\n 2\n"
                 "15\n"
                 "0 7 15# comment right after a number\n"
                 "15\t15 15\r\n"
                 "#\n"
                 "1 2 3   4 5 6\n");
    const auto image = load_image(folder.file("p3.ppm"));
    ASSERT_EQ(image->width, 2);
    ASSERT_EQ(image->height, 2);
    EXPECT_EQ(texel_at(*image, 0, 0), (Texel{0, 119, 255, 255}));
    EXPECT_EQ(texel_at(*image, 1, 0), (Texel{255, 255, 255, 255}));
    EXPECT_EQ(texel_at(*image, 0, 1), (Texel{17, 34, 51, 255}));
    EXPECT_EQ(texel_at(*image, 1, 1), (Texel{68, 85, 102, 255}));
}

TEST(ImageLoader, ReadsAsciiPpmWithMaxval255Unchanged) {
    TempFolder folder;
    folder.write("p3.ppm", "P3\n# GIMP style\n3 1\n255\n0 1 2\n127 128 129\n253 254 255\n");
    const auto image = load_image(folder.file("p3.ppm"));
    EXPECT_EQ(texel_at(*image, 0, 0), (Texel{0, 1, 2, 255}));
    EXPECT_EQ(texel_at(*image, 1, 0), (Texel{127, 128, 129, 255}));
    EXPECT_EQ(texel_at(*image, 2, 0), (Texel{253, 254, 255, 255}));
}

TEST(ImageLoader, ScalesPpmSamplesRoundingToNearest) {
    TempFolder folder;
    // maxval 100: 50 -> 127.5 -> 128 (halves up), 1 -> 2.55 -> 3, 99 -> 252.45 -> 252.
    folder.write("p3.ppm", "P3 1 1 100 50 1 99");
    EXPECT_EQ(texel_at(*load_image(folder.file("p3.ppm")), 0, 0), (Texel{128, 3, 252, 255}));
}

// ---------------------------------------------------------------------------------------
// Errors

TEST(ImageLoader, ReportsMissingFilesAndFolders) {
    TempFolder folder;
    expect_image_error(folder.file("nothing_here.png"), "no such file");
    fs::create_directory(folder.file("folder.png"));
    expect_image_error(folder.file("folder.png"), "not a file");
}

TEST(ImageLoader, ReportsEmptyAndUnrecognisedFiles) {
    TempFolder folder;
    folder.write("empty.png", "");
    expect_image_error(folder.file("empty.png"), "empty file");
    folder.write("garbage.png", "this is not an image at all");
    expect_image_error(folder.file("garbage.png"), "unsupported image format");
    folder.write("grey.pgm", "P5 1 1 255\n\x10");
    expect_image_error(folder.file("grey.pgm"), "unsupported image format");
}

TEST(ImageLoader, ReportsCorruptPng) {
    TempFolder folder;
    std::vector<std::uint8_t> rgb(32 * 32 * 3, 90);
    ASSERT_TRUE(stbi_write_png(folder.file("whole.png").c_str(), 32, 32, 3, rgb.data(), 32 * 3));
    const std::string whole = read_bytes(folder.file("whole.png"));
    folder.write("cut.png", whole.substr(0, whole.size() / 2));
    expect_image_error(folder.file("cut.png"), "corrupt PNG: ");
}

TEST(ImageLoader, ReportsTruncatedPpm) {
    TempFolder folder;
    folder.write("p3.ppm", "P3 2 2 255\n1 2 3 4 5 6 7 8 9 10 11\n");  // one sample short
    expect_image_error(folder.file("p3.ppm"), "truncated PPM data");
    folder.write("p6.ppm", "P6 2 2 255\n" + std::string(11, '\x7f'));
    expect_image_error(folder.file("p6.ppm"), "truncated PPM data");
    folder.write("p6_no_raster.ppm", "P6 2 2 255");
    expect_image_error(folder.file("p6_no_raster.ppm"), "truncated PPM data");
    folder.write("header.ppm", "P3 2 # no height or maxval\n");
    expect_image_error(folder.file("header.ppm"), "truncated PPM header");
    // A header claiming a huge raster fails at once instead of allocating it.
    folder.write("huge.ppm", "P6 1000000 1000000 255\n\x01\x02\x03");
    expect_image_error(folder.file("huge.ppm"), "truncated PPM data");
}

TEST(ImageLoader, ReportsInvalidPpmValues) {
    TempFolder folder;
    folder.write("over.ppm", "P3 1 1 15 1 2 16");
    expect_image_error(folder.file("over.ppm"), "sample 16 exceeds maxval 15");
    folder.write("maxval.ppm", "P3 1 1 70000 1 2 3");
    expect_image_error(folder.file("maxval.ppm"), "maxval 70000 is not in 1..65535");
    folder.write("zero.ppm", "P3 0 1 255");
    expect_image_error(folder.file("zero.ppm"), "zero width or height");
    folder.write("letters.ppm", "P3 1 1 255 1 2 x");
    expect_image_error(folder.file("letters.ppm"), "corrupt PPM");
    folder.write("glued.ppm", "P3 1 1 255 1 2 3x");
    expect_image_error(folder.file("glued.ppm"), "corrupt PPM");
}

// ---------------------------------------------------------------------------------------
// Placeholder and Image

TEST(ImageLoader, PlaceholderIsAnOpaqueMagentaAndGreyChecker) {
    const auto image = make_placeholder_image("missing.png");
    EXPECT_EQ(image->path, "missing.png");
    ASSERT_EQ(image->width, 8);
    ASSERT_EQ(image->height, 8);
    EXPECT_EQ(texel_at(*image, 0, 0), (Texel{255, 0, 255, 255}));
    EXPECT_EQ(texel_at(*image, 1, 0), (Texel{128, 128, 128, 255}));
    EXPECT_EQ(texel_at(*image, 0, 1), (Texel{128, 128, 128, 255}));
    EXPECT_EQ(texel_at(*image, 7, 7), (Texel{255, 0, 255, 255}));
    EXPECT_FALSE(image->has_transparency());
}

TEST(Image, HasTransparencyMeansSomeAlphaBelow255) {
    Image image;
    image.width = 2;
    image.height = 1;
    image.rgba = {0, 0, 0, 255, 0, 0, 0, 255};
    EXPECT_FALSE(image.has_transparency());
    image.rgba[7] = 254;
    EXPECT_TRUE(image.has_transparency());
}

}  // namespace
}  // namespace clr
