// Inputs that the fuzzers (fuzz/, scripts/fuzz.sh) found to break a loader, kept byte for
// byte so that the bug stays fixed. Each test says what the input did and what it must do
// now; docs/robustness.md lists the findings.
#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <string>
#include <vector>

#include "core/errors.h"
#include "scene/image_loader.h"
#include "scene/scene_loader.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

using testing::TempFolder;

template <std::size_t N>
std::string bytes_of(const char (&literal)[N]) {
    return std::string(literal, N - 1);  // every byte, NULs included, but not the terminator
}

// The reason load_image gives for the file holding `bytes`, or "" when it reads it.
std::string load_failure(const std::string& bytes) {
    TempFolder folder;
    try {
        load_image(folder.write("input", bytes));
    } catch (const ImageError& error) {
        return error.what();
    }
    return "";
}

// Found by the image fuzzer (JPEG corpus): a DHT segment whose fourth Huffman table declares
// 622 codes. stb_image 2.27 (Debian 12's libstb) wrote them past its 256-entry tables, a
// heap buffer overflow with bytes from the file (AddressSanitizer: index 257 out of bounds
// in stbi__build_huffman). JPEG is now decoded by libjpeg-turbo, which refuses the table.
TEST(FuzzRegression, JpegHuffmanTableWithTooManyCodesIsRefused) {
    const char kFinding[] =
        "\xFF\xD8\xFF\xE0\x00\x10\x4A\x46\x49\x46\x00\x01\x01\x00\x00\x01\x00\x01\x00\x00\xFF\xDB\x00\x84"
        "\x00\x03\x02\x02\x03\x02\x02\x03\x03\x03\x03\x04\x03\x03\x04\x05\x08\x05\x05\x04\x04\x05\x0A\x07"
        "\x07\x06\x08\x0C\x0A\x0C\x0C\x0B\x0A\x0B\x0B\x0D\x0E\x12\x10\x0D\x0E\x11\x0E\x0B\x0B\x10\x16\x10"
        "\x11\x13\x14\x15\x15\x15\x0C\x0F\x17\x18\x16\x14\x18\x12\x14\x15\x14\x01\x03\x04\x04\x05\x04\x05"
        "\x09\x05\x05\x09\x14\x0D\x0B\x0D\x14\x14\x14\x14\x14\x14\x14\x14\x14\x14\x14\x14\x14\x14\x14\x14"
        "\x14\x14\x14\x14\x14\x14\x14\x14\x14\x14\x14\x14\x14\x14\x14\x14\x14\x14\x14\x14\x14\x14\x14\x14"
        "\x14\x14\x14\x14\x14\x14\x14\x14\x14\x14\xFF\xC0\x00\x11\x08\x00\x07\x00\x0A\x03\x01\x22\x00\x02"
        "\x11\x01\x03\x11\x01\xFF\xC4\x01\xA2\x00\x00\x01\x05\x01\x01\x01\x01\x01\x01\x00\x00\x00\x00\x00"
        "\x00\x00\x00\x01\x02\x03\x04\x05\x06\x07\x08\x09\x0A\x0B\x10\x00\x02\x01\x03\x03\x02\x04\x03\x05"
        "\x05\x04\x04\x00\x00\x01\x7D\x01\x02\x03\x00\x04\x11\x05\x12\x21\x31\x41\x06\x13\x51\x61\x07\x22"
        "\x71\x14\x32\x81\x91\xA1\x08\x23\x42\xB1\xC1\x15\x52\xD1\xF0\x24\x33\x62\x72\x82\x09\x0A\x16\x17"
        "\x18\x19\x1A\x25\x26\x27\x28\x29\x2A\x34\x35\x36\x37\x38\x39\x3A\x43\x44\x45\x46\x47\x48\x49\x4A"
        "\x53\x54\x55\x56\x57\x58\x59\x5A\x63\x64\x65\x66\x67\x68\x69\x6A\x73\x74\x75\x76\x77\x78\x79\x7A"
        "\x83\x84\x85\x86\x87\x88\x89\x8A\x92\x93\x94\x95\x96\x97\x98\x99\x9A\xA2\xA3\xA4\xA5\xA6\xA7\xA8"
        "\xA9\xAA\xB2\xB3\xB4\xB5\xB6\xB7\xB8\xB9\xBA\xC2\xC3\xC4\xC5\xC6\xC7\xC8\xC9\xCA\xD2\xD3\xD4\xD5"
        "\xD6\xD7\xD8\xD9\xDA\xE1\xE2\xE3\xE4\xE5\xE6\xE7\xE8\xE9\xEA\xF1\xF2\xF3\xF4\xF5\xF6\xF7\xF8\xF9"
        "\xFA\x01\x00\x03\x01\x01\x01\x01\x01\x01\x01\x01\x01\x00\x00\x00\x00\x00\x00\x01\x02\x03\x04\x05"
        "\x06\x07\x08\x09\x0A\x0B\x11\x00\xFF\xD0\x02\x04\x04\x03\x04\x07\x05\x04\x04\x00\x01\x02\x77\x00"
        "\x01\x02\x03\x11\x04\x05\x21\x31\x06\x12\x41\x51\x07\x61\x71\x13\x22\x32\x81\x08\x14\x42\x91\xA1"
        "\xB1\xC1\x09\x23\x33\x52\xF0\x15\x62\x72\xD1\x0A\x16\x24\x34\xE1\x25\xF1\x17\x18\x19\x1A\x26\x27"
        "\x28\x29\x2A\x35\x36\x37\x38\x39\x3A\x43\x44\x45\x46\x47\x48\x49\x4A\x53\xAB\xAA\xA9\xA8\xA7\xA6"
        "\xA5\x9C\x64\x65\x66\x67\x68\x69\x6A\x73\x74\x75\x76\x77\x78\x79\x7A\x82\x83\x84\x85\x86\x87\x88"
        "\x89\x8A\x92\x93\x94\x95\x96\x97\x98\x99\x9A\xA2\xA3\xA4\xA5\xA6\xA7\xA8\xA9\xAA\xB2\xB3\xB4\xB5"
        "\xB6\xB7\xB8\xB9\xBA\xC2\xC3\xC4\xC5\xC6\xC7\xC8\xC9\xCA\xD2\xD3\xD4\xD5\xD6\xD7\xD8\xD9\xDA\xE2"
        "\xE3\xE4\xE5\xE6\xE7\xE8\xE9\xEA\xF2\xF3\xF4\xF5\xF6\xF7\xF8\xF9\xFA\xFF\xDA\x00\x0C\x03\x01\x00"
        "\x02\x11\x03\x11\x00\x3F\x00\xE8\xFE\x13\xDD\xC5\xE1\x6B\xC8\x5F\x4D\x31\xAF\x87\x6F\x74\x9D\x45"
        "\x62\xB2\x75\x0A\x12\x44\xD2\xAF\x27\x64\x11\xAC\x61\x56\x00\x1B\x6A\xAE\x49\x18\xC7\x4E\x49\x69"
        "\xAF\xE9\x7A\x35\xAC\x3A\x7C\xDA\xC6\xAD\x73\x2D\xA2\x2C\x0F\x32\x6D\x8D\x64\x65\x1B\x4B\x05\x2A"
        "\xDB\x41\xC6\x71\x93\x8F\x53\xD6\xB3\x3C\x0B\xFF\x00\x20\x4F\x0E\xFF\x00\xD7\x86\xB7\xFF\x00\xA8"
        "\xFD\xDD\x73\x7A\xAF\xFC\x85\x2F\x3F\xEB\xB3\xFF\x00\xE8\x46\xBE\x47\x8E\x5C\xF2\xCA\x54\xDE\x16"
        "\x4E\x3C\xF2\x7C\xDE\x7C\xB1\x56\xBF\x9A\xE6\x6A\xFB\xB5\x6B\xDD\xEA\x7B\xF9\x36\x51\x97\xE7\xCA"
        "\x92\xCC\xA8\xC6\xA2\x94\x67\x37\x75\xF6\x94\xD4\x6F\xF7\x5E\xFD\x2E\xDB\x3F\xFF\xD9";
    EXPECT_EQ(load_failure(bytes_of(kFinding)), "corrupt JPEG: Bogus Huffman table definition");
}

// A valid JPEG whose comment happens to hold the bytes of a Huffman table segment (FF C4)
// still loads: the decoder follows the segments, it does not search for markers.
TEST(FuzzRegression, HuffmanTableBytesInACommentLeaveValidJpegsAlone) {
    std::string jpeg;
    const std::vector<unsigned char> rgb(8 * 8 * 3, 128);
    stbi_write_jpg_to_func([](void* out, void* data, int size) { static_cast<std::string*>(out)->append(static_cast<char*>(data), size); },
                           &jpeg, 8, 8, 3, rgb.data(), 90);
    ASSERT_EQ(jpeg.substr(0, 2), "\xFF\xD8");
    // A COM segment right after the start-of-image marker: "FF C4", a table id and 16 counts
    // of 16 codes each, 256 in all, the most a table may have.
    const std::string comment = std::string("\xFF\xC4\x00\x00\x00", 5) + std::string(16, '\x10');
    const std::string segment = std::string("\xFF\xFE", 2) + char(0) + char(comment.size() + 2) + comment;
    EXPECT_EQ(load_failure(jpeg.substr(0, 2) + segment + jpeg.substr(2)), "");
}

// Found by the image fuzzer (JPEG corpus) in a CI run: a progressive JPEG whose AC scan
// decodes with AC table 0, which no DHT segment defines. stb_image 2.27 allocates its decoder
// without clearing it and indexed the undefined table with garbage (UndefinedBehaviorSanitizer:
// index out of bounds in stbi__jpeg_huff_decode). libjpeg-turbo, which decodes JPEG now,
// refuses it at a scan's parameters, before any table is used.
TEST(FuzzRegression, JpegScanWithAnUndefinedHuffmanTableIsRefused) {
    const char kFinding[] =
        "\xFF\xD8\xFF\xE0\x00\x10\x4A\x46\x49\x46\x00\x01\x01\x21\x00\x00\x01\x00\x01\x00\x00\xFF\xDB\x00"
        "\x43\x00\x08\x06\x06\x07\x06\x05\x08\x07\x07\x07\x09\x09\x08\x0A\x0C\x14\x0D\x0C\x0B\x0B\x0C\x19"
        "\x12\x13\x0F\x14\x1D\x1A\x1F\x1E\x1D\x1A\x1C\x1C\x20\x24\x2E\x27\x20\x22\x2C\x23\x1C\x1C\x28\x33"
        "\x29\x2C\x30\x31\xFF\x00\x34\x34\x34\x1F\x27\x39\x3D\x38\x32\x3C\x2E\x33\x34\x32\xFF\xC2\x00\x0B"
        "\x08\x00\x11\x00\x18\x01\x01\x11\x00\xFF\xC4\x00\x16\x00\x01\x01\x01\x00\x00\x00\x00\x00\x00\x00"
        "\x00\x00\x00\x00\x00\x00\x02\x04\x01\xFF\xDA\x00\x08\x01\x01\x00\x00\x00\x26\x10\x01\x00\x02\x02"
        "\x02\x02\x03\x00\x00\x00\x00\x00\x00\x00\x00\x00\x01\xC7\x21\x00\x31\x41\x51\x91\xF0\x10\x61\x71"
        "\xFF\xDA\x00\x08\x01\x01\x00\x01\x3F\x21\xB9\x32\x90\xAE\x40\x08\x8C\x32\x98\xCA\x36\x0A\x78\x48"
        "\xF1\x92\xE9\xC7\x0D\x87\x93\x13\xAE\x70\x1E\x91\xAA\x70\x98\xAD\x8C\x3F\xBC\xB0\x03\x40\x8F\xB1"
        "\x90\x37\x53\xB6\x6C\xCC\x71\x4B\x3D\xEF\x6C\xF7\x1D\x7C\x08\xFF\xDA\x00\x08\x01\x01\x00\x00\x00"
        "\x10\xFF\xD8\xFF\xE0\x00\x10\x4A\x46\x49\x46\x00\x01\x01\x21\x00\x00\x01\x00\x01\x00\x00\xFF\xDB"
        "\x00\x43\x00\x08\x06\x06\x07\x06\x05\x08\x07\x07\x07\x09\x09\x08\x0A\x0C\x14\x0D\x0C\x0B\x0B\x0C"
        "\x19\x12\x13\x0F\x14\x1D\x1A\x1E\x1A\x1D\x1F\x1C\x1C\x20\x24\x2E\x27\x20\x22\x2C\x23\x1C\x1C\x28"
        "\x37\x29\x2C\x30\x31\xFF\x00\x34\x34\x34\x1F\x27\x39\x3D\x38\x32\x3C\x2E\x33\x34\x32\xFF\xC2\x00"
        "\x0B\x08\x00\x11\x00\x18\x01\x01\x11\x00\xFF\xC4\x00\x16\x00\x01\x01\x01\x00\x00\x00\x00\x00\x00"
        "\x00\x00\x00\x00\x00\x00\x00\x02\x04\x01\xFF\x01\x11\x00\x01\x01\x00\x00\x00\x01\xA1\xEC\x8B\xDA"
        "\xFF\xDA\xC4\x1E\x00\x10\x00\x02\x01\x03\x05\x00\x00\x00\x01\x13\x00\x00\x00\x00\x00\x00\x02\x03"
        "\x01\x04\x13\x34\x00\x11\x24\x31\x93\x13\xAE\x70\xFB\xFE\xFE\x87\xFF\x00\xFF\xD9\x29\x2C\x30\x31"
        "\xFF\x00\x34\x34\x34\x1F\x27\x39\x3D\x38\x32\x3C\x2E\x33\x34\x32\xFF\xC2\x00\x0B\x08\x00\x11\x00"
        "\x18\x01\x01\x11\x00\xFF\xC4\x00\x16\x00\x01\x01\x01\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00"
        "\x00\x00\x02\x04\x01\xFF\xDA\x00\x08\x01\x01\x00\x00\x00\x01\xA1\xEC\x8B\xDA\xFF\xDA\xC4\x1E\x00"
        "\x10\x00\x02\x01\x03\x05\x00";
    EXPECT_EQ(load_failure(bytes_of(kFinding)), "corrupt JPEG: Invalid progressive parameters Ss=0 Se=0 Ah=2 Al=6");
}

// A valid baseline JPEG whose AC table 0 is renamed AC table 2: its scans still decode with
// AC table 0, which is now never defined. stb indexed the undefined table. libjpeg-turbo
// takes JPEG's standard tables for a table never defined (as Motion JPEG frames expect), and
// those are the tables stb's writer uses: the picture is the original's, never garbage.
TEST(FuzzRegression, JpegScanUsingATableNeverDefinedTakesTheStandardTable) {
    std::string jpeg;
    const std::vector<unsigned char> rgb(16 * 16 * 3, 90);
    stbi_write_jpg_to_func([](void* out, void* data, int size) { static_cast<std::string*>(out)->append(static_cast<char*>(data), size); },
                           &jpeg, 16, 16, 3, rgb.data(), 90);
    ASSERT_EQ(load_failure(jpeg), "");
    TempFolder folder;
    const std::vector<std::uint8_t> original = load_image(folder.write("original.jpg", jpeg))->rgba;
    const std::size_t dht = jpeg.find("\xFF\xC4");
    ASSERT_NE(dht, std::string::npos);
    bool renamed = false;
    for (std::size_t table = dht + 4; table < jpeg.size() && !renamed;) {  // the segment's tables
        std::size_t codes = 0;
        for (int length = 1; length <= 16; ++length) codes += static_cast<unsigned char>(jpeg[table + length]);
        if (jpeg[table] == '\x10') {
            jpeg[table] = '\x12';
            renamed = true;
        }
        table += 17 + codes;
    }
    ASSERT_TRUE(renamed) << "stb's JPEG writer defines AC table 0 in its first DHT segment";
    EXPECT_EQ(load_image(folder.write("renamed.jpg", jpeg))->rgba, original);
}

// Every JPEG that stb writes, baseline at several qualities and sizes, loads.
TEST(FuzzRegression, JpegsStbWritesLoad) {
    for (int quality : {10, 50, 90, 100}) {
        for (int size : {1, 8, 17, 64}) {
            std::string jpeg;
            std::vector<unsigned char> rgb(size * size * 3);
            for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<unsigned char>(i * 37);
            stbi_write_jpg_to_func(
                [](void* out, void* data, int length) { static_cast<std::string*>(out)->append(static_cast<char*>(data), length); },
                &jpeg, size, size, 3, rgb.data(), quality);
            EXPECT_EQ(load_failure(jpeg), "") << "quality " << quality << ", " << size << "x" << size;
        }
    }
}

// Found by the image fuzzer (PNG corpus): a 16-bit PNG whose first IDAT chunk is empty. stb
// copies its zero bytes with memcpy from a null buffer, undefined behaviour by the letter of
// C (UndefinedBehaviorSanitizer: null pointer passed as argument 1) though harmless on every
// C library; the fuzz build turns that one check off for stb (fuzz/CMakeLists.txt). The
// file's second IDAT chunk is corrupt, and its unknown chunk type comes back as printable
// escapes rather than raw bytes.
TEST(FuzzRegression, PngWithEmptyFirstIdatChunkIsACleanError) {
    const char kFinding[] =
        "\x89\x50\x4E\x47\x0D\x0A\x1A\x0A\x00\x00\x00\x0D\x49\x48\x44\x52\x00\x00\x00\x05\x00\x00\x00\x03"
        "\x10\x04\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x49\x44\x41\x54\x78\x9C\x63\x60\x00\x82\x69"
        "\x53\x4F\x58\xE9\x6A\xC5\x9D\x3F\xBC\xFF\x6B\x4A\x54\x48\xF7\x4F\x06\xC7\xD7\xC5\x13\x6E\x34\x70"
        "\xA9\xE6\x8B\x2E\xD8\xC5\xBA\xCA\xDC\x7F\x3B\xFD\xD9\x27\x16\x49\x44\x41\x54\x78\x01\x63\x60\x00"
        "\x82\xA9\x56\xF7\x5B\xB4\xCE\x97\x48\xEE\x4F\xE1\x5C\x17\xF2\x73\x9E\x04\x2A\x05\xDA\x00\x00\x00"
        "\x16\x49\x45\x4E\x44\xAE\x42\x60\x82";
    const std::string failure = load_failure(bytes_of(kFinding));
    EXPECT_EQ(failure.rfind("corrupt PNG: ", 0), 0u) << failure;
    for (const char c : failure) EXPECT_TRUE(c >= 0x20 && c < 0x7F) << "unprintable byte in: " << failure;
}

// Found by the image fuzzer (JPEG corpus): a 1.6 KB JPEG whose header claims 49680 x 255
// texels, which stb decodes (from almost no data) in about a gigabyte of memory. Images are
// now limited to the largest frame size, 8192 x 8192 pixels, checked from the header; this
// hand-made header claims 20000 x 20000.
TEST(FuzzRegression, HugeImageDimensionsAreRefusedBeforeDecoding) {
    const std::string jpeg_header = std::string("\xFF\xD8\xFF\xC0\x00\x11\x08\x4E\x20\x4E\x20\x03\x01\x22\x00\x02\x11\x01\x03\x11\x01", 21);
    EXPECT_EQ(load_failure(jpeg_header),
              "JPEG image of 20000 x 20000 pixels is larger than the limit of 67108864 pixels (8192 x 8192)");
}

bool is_printable_line(const std::string& text) {
    for (const char c : text)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) return false;
    return true;
}

// Found by the scene fuzzer: a syntax error whose message quotes the text it stopped at,
// DEL characters (0x7F) included. Messages quote the file, and each is printed as one line,
// so control characters now appear as \xNN escapes.
TEST(FuzzRegression, SyntaxErrorQuotesControlCharactersAsEscapes) {
    const char kFinding[] = "\x20\x20\x22\x66\x6D\x2C\x20\x7F\x7F\x5D\x51\x75\x6E\x7F\x7F\x72";
    try {
        parse_scene(bytes_of(kFinding), "scene.json");
        ADD_FAILURE() << "the text is not JSON";
    } catch (const SceneError& error) {
        EXPECT_TRUE(is_printable_line(error.what())) << error.what();
        EXPECT_NE(std::string(error.what()).find("\\x7F\\x7F]Qun"), std::string::npos) << error.what();
    }
}

// The same for keys: a JSON escape puts an escape character, or a line break, in a key, and
// the key appears in the location of an error or warning.
TEST(FuzzRegression, KeysWithControlCharactersAreEscapedInMessages) {
    const std::string camera = R"("eye": [0, 0, 5], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60, "width": 4, "height": 3)";
    const Scene scene = parse_scene("{" + camera + R"(, "\u001b[2J": 1, "a\nclrender: error: forged": 2})", "scene.json");
    ASSERT_EQ(scene.warnings.size(), 2u);
    for (const std::string& warning : scene.warnings) EXPECT_TRUE(is_printable_line(warning)) << warning;
    EXPECT_EQ(scene.warnings[0], "/\\x1B[2J: unknown key (ignored)");
    EXPECT_EQ(scene.warnings[1], "/a\\x0Aclrender: error: forged: unknown key (ignored)");
}

}  // namespace
}  // namespace clr
