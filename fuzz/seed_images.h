// Small, deterministic image files in each variant clrender's decoders read, for the
// fuzzers' seed corpus. A fuzzer mutates what it is given; a seed that already reaches a
// decoder path (an interlaced 2-bit palette PNG, a progressive JPEG, a 16-bit PPM) saves it
// from having to discover the format's structure byte by byte.
#pragma once

#include <string>
#include <vector>

namespace clr::fuzz {

// PNG colour types (the values of the IHDR field).
enum class PngColor : int { Grey = 0, Rgb = 2, Palette = 3, GreyAlpha = 4, Rgba = 6 };

struct PngSpec {
    int width = 5;
    int height = 3;
    PngColor color = PngColor::Rgba;
    int bit_depth = 8;           // 1, 2 or 4 (grey and palette only), 8, or 16 (not palette)
    bool interlaced = false;     // Adam7
    bool vary_filters = false;   // cycle through the five row filters instead of always None
    bool transparency = false;   // tRNS: alpha per palette entry, or a grey or RGB colour key
    int zlib_level = 6;          // 0 writes stored (uncompressed) deflate blocks only
    bool fixed_huffman = false;  // deflate with fixed codes (Z_FIXED) instead of dynamic ones
    int idat_chunks = 1;         // split the compressed stream over this many IDAT chunks
    bool text_chunk = false;     // an ancillary tEXt chunk, which a decoder must skip
};

// A complete PNG file, written with zlib.
std::string encode_png(const PngSpec& spec);

struct JpegSpec {
    int width = 16;
    int height = 16;
    int components = 3;         // 1: greyscale, 3: RGB stored as YCbCr, 4: CMYK (Adobe marker)
    int quality = 75;
    int h_sampling = 2;         // sampling factors of the first component: 2x2 is 4:2:0,
    int v_sampling = 2;         // 2x1 is 4:2:2, 1x1 is 4:4:4
    bool progressive = false;
    int restart_rows = 0;       // a restart marker every this many MCU rows (0: none)
    bool optimize_huffman = false;
};

// A complete JPEG file, written with libjpeg.
std::string encode_jpeg(const JpegSpec& spec);

struct PpmSpec {
    int width = 5;
    int height = 3;
    int maxval = 255;       // above 255: two bytes a sample (P6) or larger numbers (P3)
    bool ascii = false;     // P3 instead of P6
    bool comments = false;  // '#' comments between the header fields (and, in P3, the samples)
};

// A complete PPM file.
std::string encode_ppm(const PpmSpec& spec);

// The images that the seed scenes name, as (file name, bytes): the scene fuzzer writes them
// beside its scene file, so that a scene's billboards reach the image code through the
// loader as they do in clrender. The names include the demo scene's.
struct NamedFile {
    std::string name;
    std::string bytes;
};
std::vector<NamedFile> scene_images();

// The test pattern every encoder draws: channel `channel` of pixel (x, y) as a value in
// 0..maxval, with gradients, edges and both extremes, the same on every machine.
unsigned pattern_sample(int x, int y, int channel, unsigned maxval);

}  // namespace clr::fuzz
