// The PNG's compressed pixel data: inflated by zlib (as every PNG reader does), it is exactly
// the rows with the Up filter, RGB or RGBA, computed here independently; and the files it goes
// into have their chunks in order, each with a correct CRC.
#include "output/png_pixel_data.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "output/image_writer.h"
#include "output/png_reader.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

using testing::read_bytes;
using testing::TempFolder;

// Pseudo-random texels (alpha too), so that every byte of a row differs from the byte above.
Image noise_image(int width, int height, bool write_alpha) {
    Image image;
    image.width = width;
    image.height = height;
    image.write_alpha = write_alpha;
    std::uint32_t state = 987654321u;
    for (int i = 0; i < width * height * 4; ++i) {
        state = state * 1664525u + 1013904223u;
        image.rgba.push_back(static_cast<std::uint8_t>(state >> 24));
    }
    return image;
}

// What the PNG standard says the filtered data is: each row, a 2 ("Up"), then each byte minus
// the byte above it, modulo 256.
std::vector<std::uint8_t> up_filtered_rows(const Image& image) {
    const int channels = image.write_alpha ? 4 : 3;
    std::vector<std::uint8_t> rows;
    for (int y = 0; y < image.height; ++y) {
        rows.push_back(2);
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < channels; ++c) {
                const int above = y > 0 ? image.at(x, y - 1, c) : 0;
                rows.push_back(static_cast<std::uint8_t>(image.at(x, y, c) - above));
            }
    }
    return rows;
}

std::vector<std::uint8_t> inflated(const std::vector<std::uint8_t>& stream, std::size_t expected_size) {
    std::vector<std::uint8_t> data(expected_size + 1);  // one byte more: a longer stream would show
    uLongf size = data.size();
    const int result = uncompress(data.data(), &size, stream.data(), stream.size());
    EXPECT_EQ(result, Z_OK) << "not a complete zlib stream";
    data.resize(size);
    return data;
}

TEST(PngPixelData, InflatesToTheUpFilteredRgbRows) {
    // 77 rows: two full strips of compressor input and a part one; an odd width.
    const Image image = noise_image(45, 77, false);
    const std::vector<std::uint8_t> expected = up_filtered_rows(image);
    EXPECT_EQ(inflated(png_pixel_data(image), expected.size()), expected);
}

TEST(PngPixelData, KeepsAlphaForAnRgbaPng) {
    const Image image = noise_image(8, 33, true);
    const std::vector<std::uint8_t> expected = up_filtered_rows(image);
    ASSERT_EQ(expected.size(), 33u * (1 + 8 * 4));
    EXPECT_EQ(inflated(png_pixel_data(image), expected.size()), expected);
}

TEST(PngPixelData, OnePixel) {
    const Image image = noise_image(1, 1, false);
    const std::vector<std::uint8_t> expected = up_filtered_rows(image);
    EXPECT_EQ(inflated(png_pixel_data(image), expected.size()), expected);
}

TEST(PngPixelData, FlatRowsCompressWell) {
    Image image;
    image.width = 640;
    image.height = 480;
    image.rgba.assign(static_cast<std::size_t>(640) * 480 * 4, 90);
    const std::vector<std::uint8_t> data = png_pixel_data(image);
    EXPECT_LT(data.size(), 640u * 480 * 3 / 100) << "a flat image filters to zeros";
    EXPECT_EQ(inflated(data, up_filtered_rows(image).size()), up_filtered_rows(image));
}

TEST(PngPixelData, SameImageGivesTheSameBytes) {
    const Image image = noise_image(300, 200, false);
    EXPECT_EQ(png_pixel_data(image), png_pixel_data(image));
}

struct Chunk {
    std::string type;
    std::size_t size = 0;
    bool crc_ok = false;
};

std::uint32_t big_endian(const std::string& bytes, std::size_t at) {
    return (std::uint32_t(std::uint8_t(bytes[at])) << 24) | (std::uint32_t(std::uint8_t(bytes[at + 1])) << 16) |
           (std::uint32_t(std::uint8_t(bytes[at + 2])) << 8) | std::uint32_t(std::uint8_t(bytes[at + 3]));
}

// The file's chunks after the signature, each with whether its CRC (over type and data) holds.
std::vector<Chunk> chunks_of(const std::string& png) {
    std::vector<Chunk> chunks;
    std::size_t at = 8;
    while (at + 12 <= png.size()) {
        Chunk chunk;
        chunk.size = big_endian(png, at);
        if (at + 12 + chunk.size > png.size()) break;
        chunk.type = png.substr(at + 4, 4);
        const auto* typed = reinterpret_cast<const Bytef*>(png.data() + at + 4);
        chunk.crc_ok = crc32(0, typed, static_cast<uInt>(4 + chunk.size)) == big_endian(png, at + 8 + chunk.size);
        chunks.push_back(chunk);
        at += 12 + chunk.size;
    }
    EXPECT_EQ(at, png.size()) << "bytes after the last whole chunk";
    return chunks;
}

TEST(PngPixelData, FilesHaveHeaderTextDataAndEndChunksWithCorrectCrcs) {
    TempFolder folder;
    // Noise does not compress: over 2 MiB of pixel data, in chunks of at most 1 MiB.
    const Image image = noise_image(900, 800, false);
    write_image(folder.file("noise.png"), image, {{"Title", "noise"}});
    const std::string png = read_bytes(folder.file("noise.png"));
    ASSERT_EQ(png.substr(0, 8), "\x89PNG\r\n\x1a\n");
    const std::vector<Chunk> chunks = chunks_of(png);
    std::string types;
    for (const Chunk& chunk : chunks) {
        EXPECT_TRUE(chunk.crc_ok) << chunk.type;
        if (chunk.type == "IDAT") {
            EXPECT_LE(chunk.size, std::size_t{1} << 20);
        }
        if (types.empty() || chunk.type != types.substr(types.size() - 4)) types += chunk.type;
    }
    EXPECT_EQ(types, "IHDRsRGBtEXtIDATIEND");
    int data_chunks = 0;
    for (const Chunk& chunk : chunks) data_chunks += chunk.type == "IDAT";
    EXPECT_GE(data_chunks, 3);
    ASSERT_FALSE(chunks.empty());
    EXPECT_EQ(chunks.back().size, 0u);
    // libpng checks every CRC and the zlib stream's checksum as it decodes.
    const Image decoded = read_png_pixels(folder.file("noise.png"), image.width, image.height);
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        ASSERT_TRUE(std::equal(image.rgba.begin() + i, image.rgba.begin() + i + 3, decoded.rgba.begin() + i)) << i / 4;
    }
}

}  // namespace
}  // namespace clr
