// Valid JPEGs of kinds clrender does not decode (arithmetic-coded, lossless, two components)
// are refused by name, not called corrupt; and JPEG and PNG headers claiming more pixels than
// the limit say so, instead of stb's "unknown image type" (scene/jpeg_checks.h).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <jpeglib.h>

#include "scene/image_loader.h"
#include "support/png_header.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

using testing::TempFolder;

// load_image's message for the file at `path`, or "" when it decodes.
std::string refusal(const std::string& path) {
    try {
        load_image(path);
    } catch (const ImageError& error) {
        return error.what();
    }
    return "";
}

// A 16 x 16 JPEG written by libjpeg with `components` components of colour space `space`,
// Huffman- or arithmetic-coded.
void write_jpeg(const std::string& path, int components, J_COLOR_SPACE space, bool arithmetic) {
    FILE* file = std::fopen(path.c_str(), "wb");
    ASSERT_NE(file, nullptr);
    jpeg_compress_struct cinfo{};
    jpeg_error_mgr errors{};
    cinfo.err = jpeg_std_error(&errors);
    jpeg_create_compress(&cinfo);
    jpeg_stdio_dest(&cinfo, file);
    cinfo.image_width = 16;
    cinfo.image_height = 16;
    cinfo.input_components = components;
    cinfo.in_color_space = space;
    jpeg_set_defaults(&cinfo);
    cinfo.arith_code = arithmetic ? TRUE : FALSE;
    jpeg_start_compress(&cinfo, TRUE);
    std::vector<JSAMPLE> row(16 * components);
    for (int x = 0; x < 16 * components; ++x) row[x] = static_cast<JSAMPLE>(x * 7);
    while (cinfo.next_scanline < cinfo.image_height) {
        JSAMPROW rows[] = {row.data()};
        jpeg_write_scanlines(&cinfo, rows, 1);
    }
    jpeg_finish_compress(&cinfo);
    jpeg_destroy_compress(&cinfo);
    std::fclose(file);
}

TEST(JpegVariants, TheSameImageHuffmanCodedDecodesArithmeticCodedIsNamed) {
    TempFolder folder;
    write_jpeg(folder.file("huffman.jpg"), 3, JCS_RGB, false);
    write_jpeg(folder.file("arithmetic.jpg"), 3, JCS_RGB, true);
    EXPECT_EQ(refusal(folder.file("huffman.jpg")), "");
    EXPECT_EQ(refusal(folder.file("arithmetic.jpg")),
              "unsupported JPEG: arithmetic-coded JPEG (SOF9) is not supported; clrender reads Huffman-coded baseline "
              "and progressive JPEG (save the image as PNG, or as a baseline JPEG)");
}

TEST(JpegVariants, TwoComponentsAreNamed) {
    TempFolder folder;
    write_jpeg(folder.file("two.jpg"), 2, JCS_UNKNOWN, false);
    EXPECT_EQ(refusal(folder.file("two.jpg")),
              "unsupported JPEG: 2 colour components are not supported; clrender reads JPEG of 1 (grey), 3 (colour) or "
              "4 (CMYK) components (save the image as PNG)");
    write_jpeg(folder.file("grey.jpg"), 1, JCS_GRAYSCALE, false);
    EXPECT_EQ(refusal(folder.file("grey.jpg")), "");
}

TEST(JpegVariants, LosslessIsNamed) {
    if (std::system("ffmpeg -version >/dev/null 2>&1") != 0) GTEST_SKIP() << "ffmpeg (the lossless JPEG writer) is not installed";
    TempFolder folder;
    const std::string path = folder.file("lossless.jpg");
    const std::string command = "ffmpeg -v error -y -f lavfi -i color=red:s=16x16 -frames:v 1 -c:v ljpeg -pix_fmt bgr24 "
                                "-f image2 '" + path + "'";
    ASSERT_EQ(std::system(command.c_str()), 0);
    EXPECT_NE(refusal(path).find("unsupported JPEG: lossless JPEG (SOF3) is not supported"), std::string::npos)
        << refusal(path);
}

TEST(JpegVariants, TwelveBitSamplesAreNamed) {
    // A frame header (SOF1, 12-bit samples, 16 x 16, 3 components): the refusal comes from it.
    TempFolder folder;
    folder.write("deep.jpg", std::string("\xFF\xD8\xFF\xC1\x00\x11\x0C\x00\x10\x00\x10\x03\x01\x11\x00\x02\x11\x00\x03\x11"
                                         "\x00\xFF\xD9", 23));
    EXPECT_EQ(refusal(folder.file("deep.jpg")),
              "unsupported JPEG: 12-bit samples are not supported; clrender reads 8-bit JPEG (save the image as PNG)");
}

// stb refuses these sizes too, but as "unknown image type" after trying every format.
TEST(ImageSizeLimit, HugeHeadersAreNamedAsTooLarge) {
    TempFolder folder;
    folder.write("huge.png", testing::png_header_only(100000, 100000, 8));
    EXPECT_EQ(refusal(folder.file("huge.png")),
              "PNG image of 100000 x 100000 pixels is larger than the limit of 67108864 pixels (8192 x 8192)");
    folder.write("wide.jpg", std::string("\xFF\xD8\xFF\xC0\x00\x11\x08\xFF\xFF\xFF\xFF\x03\x01\x22\x00\x02\x11\x01\x03\x11"
                                         "\x01\xFF\xD9", 23));
    EXPECT_EQ(refusal(folder.file("wide.jpg")),
              "JPEG image of 65535 x 65535 pixels is larger than the limit of 67108864 pixels (8192 x 8192)");
    // The header alone passes where it is within the limit: the size is not the refusal then.
    folder.write("ok.png", testing::png_header_only(8192, 8192, 8));
    EXPECT_EQ(refusal(folder.file("ok.png")).find("larger than the limit"), std::string::npos);
}

}  // namespace
}  // namespace clr
