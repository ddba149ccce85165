// Valid JPEGs of every kind: arithmetic-coded ones decode; those clrender does not decode
// (lossless, 12-bit, two components) are refused by name, not called corrupt; and JPEG and PNG headers claiming more pixels than
// the limit say so, instead of stb's "unknown image type" (scene/jpeg_checks.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <jpeglib.h>
#include <stb_image.h>

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
// Huffman- or arithmetic-coded; `size` x `size` with `chroma_halved` 4:2:0 (else 4:4:4).
void write_jpeg(const std::string& path, int components, J_COLOR_SPACE space, bool arithmetic, int size = 16,
                bool chroma_halved = true) {
    FILE* file = std::fopen(path.c_str(), "wb");
    ASSERT_NE(file, nullptr);
    jpeg_compress_struct cinfo{};
    jpeg_error_mgr errors{};
    cinfo.err = jpeg_std_error(&errors);
    jpeg_create_compress(&cinfo);
    jpeg_stdio_dest(&cinfo, file);
    cinfo.image_width = size;
    cinfo.image_height = size;
    cinfo.input_components = components;
    cinfo.in_color_space = space;
    jpeg_set_defaults(&cinfo);
    cinfo.arith_code = arithmetic ? TRUE : FALSE;
    if (!chroma_halved)
        for (int c = 0; c < cinfo.num_components; ++c) cinfo.comp_info[c].h_samp_factor = cinfo.comp_info[c].v_samp_factor = 1;
    jpeg_start_compress(&cinfo, TRUE);
    std::vector<JSAMPLE> row(size * components);
    while (cinfo.next_scanline < cinfo.image_height) {
        // Edges and gradients in every channel, so that chroma upsampling matters.
        for (int x = 0; x < size * components; ++x)
            row[x] = static_cast<JSAMPLE>((x * 7 + cinfo.next_scanline * 13) ^ (x * cinfo.next_scanline >> 3));
        JSAMPROW rows[] = {row.data()};
        jpeg_write_scanlines(&cinfo, rows, 1);
    }
    jpeg_finish_compress(&cinfo);
    jpeg_destroy_compress(&cinfo);
    std::fclose(file);
}

// Arithmetic coding is another lossless coding of the same coefficients: the same picture
// Huffman-coded and arithmetic-coded decodes to the same pixels (stb called the latter corrupt).
TEST(JpegVariants, ArithmeticCodedDecodesToTheHuffmanCodedPixels) {
    TempFolder folder;
    write_jpeg(folder.file("huffman.jpg"), 3, JCS_RGB, false, 48);
    write_jpeg(folder.file("arithmetic.jpg"), 3, JCS_RGB, true, 48);
    ASSERT_EQ(refusal(folder.file("arithmetic.jpg")), "");
    EXPECT_EQ(load_image(folder.file("arithmetic.jpg"))->rgba, load_image(folder.file("huffman.jpg"))->rgba);
}

// stb_image, clrender's JPEG decoder before libjpeg-turbo, as the independent reference: the
// two IDCTs round differently, but with libjpeg's smooth chroma upsampling (as stb does) no
// sample is more than a few steps off (docs/benchmarks.md, Figures behind design choices). Without it, edges
// in subsampled chroma are off by up to about a hundred.
TEST(JpegVariants, PixelsStayWithinAFewStepsOfStb) {
    TempFolder folder;
    struct Variant {
        const char* name;
        int components;
        J_COLOR_SPACE space;
        bool chroma_halved;
    };
    for (const Variant& variant : {Variant{"420.jpg", 3, JCS_RGB, true}, Variant{"444.jpg", 3, JCS_RGB, false},
                                   Variant{"grey.jpg", 1, JCS_GRAYSCALE, false}, Variant{"cmyk.jpg", 4, JCS_CMYK, false}}) {
        const std::string path = folder.file(variant.name);
        write_jpeg(path, variant.components, variant.space, false, 64, variant.chroma_halved);
        const auto image = load_image(path);
        int width = 0, height = 0, channels = 0;
        unsigned char* reference = stbi_load(path.c_str(), &width, &height, &channels, 4);
        ASSERT_NE(reference, nullptr) << variant.name;
        ASSERT_EQ(image->width, width);
        ASSERT_EQ(image->height, height);
        int largest = 0;
        for (std::size_t i = 0; i < image->rgba.size(); ++i)
            largest = std::max(largest, std::abs(int(image->rgba[i]) - int(reference[i])));
        stbi_image_free(reference);
        EXPECT_LE(largest, 5) << variant.name;
    }
}

// libjpeg fills what a damaged or cut file lacks with grey, with only a warning: clrender
// refuses such a file instead of showing made-up rows.
TEST(JpegVariants, ACutFileIsCorruptNotGreyRows) {
    TempFolder folder;
    write_jpeg(folder.file("whole.jpg"), 3, JCS_RGB, false, 64);
    ASSERT_EQ(refusal(folder.file("whole.jpg")), "");
    const std::string whole = testing::read_bytes(folder.file("whole.jpg"));
    folder.write("cut.jpg", whole.substr(0, whole.size() / 2));
    EXPECT_EQ(refusal(folder.file("cut.jpg")), "corrupt JPEG: Premature end of JPEG file");
}

TEST(JpegVariants, TwoComponentsAreNamed) {
    TempFolder folder;
    write_jpeg(folder.file("two.jpg"), 2, JCS_UNKNOWN, false);
    EXPECT_EQ(refusal(folder.file("two.jpg")),
              "unsupported JPEG: 2 colour components are not supported; clrender reads JPEG of 1 (grey), 3 (colour) or "
              "4 (CMYK) components (save the image as PNG, with alpha if the extra channel is one)");
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
    // Sides whose product is beyond 64 bits (the image fuzzer's find) are still only too large.
    folder.write("widest.png", testing::png_header_only(0xFFFFFFFFu, 0xFFFFFFFFu, 8));
    EXPECT_EQ(refusal(folder.file("widest.png")),
              "PNG image of 4294967295 x 4294967295 pixels is larger than the limit of 67108864 pixels (8192 x 8192)");
    // The header alone passes where it is within the limit: the size is not the refusal then.
    folder.write("ok.png", testing::png_header_only(8192, 8192, 8));
    EXPECT_EQ(refusal(folder.file("ok.png")).find("larger than the limit"), std::string::npos);
}

}  // namespace
}  // namespace clr
