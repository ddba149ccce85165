#include "seed_images.h"

#include <zlib.h>

// jpeglib.h needs size_t and FILE declared before it.
#include <cstddef>
#include <cstdio>
#include <jpeglib.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <vector>

namespace clr::fuzz {

unsigned pattern_sample(int x, int y, int channel, unsigned maxval) {
    // Pixel (0, 0) is black and the last column white, so every file holds 0 and maxval;
    // between them a diagonal ramp per channel, different for each channel.
    if (x == 0 && y == 0) return 0;
    if (x % 7 == 6) return maxval;
    const unsigned long long step = static_cast<unsigned long long>(x * 37 + y * 91 + channel * 53);
    return static_cast<unsigned>(step * 2654435761ULL % (maxval + 1ULL));
}

// ---------------------------------------------------------------------------------------
// PNG

namespace {

using Bytes = std::vector<std::uint8_t>;

int channels_of(PngColor color) {
    switch (color) {
        case PngColor::Grey: return 1;
        case PngColor::Rgb: return 3;
        case PngColor::Palette: return 1;
        case PngColor::GreyAlpha: return 2;
        case PngColor::Rgba: return 4;
    }
    return 0;
}

void put_u32(std::string& out, std::uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8) out += static_cast<char>((value >> shift) & 0xFF);
}

void put_chunk(std::string& out, const char* type, const std::string& data) {
    put_u32(out, static_cast<std::uint32_t>(data.size()));
    const std::string typed = std::string(type, 4) + data;
    out += typed;
    // The CRC covers the chunk type and its data, not the length.
    put_u32(out, static_cast<std::uint32_t>(
                     crc32(0, reinterpret_cast<const Bytef*>(typed.data()), static_cast<uInt>(typed.size()))));
}

// The bytes of one unfiltered row of `count` pixels starting at column x0 with step dx, on
// image row y, packed as the PNG format requires (sub-byte samples from the high bits down,
// 16-bit samples big-endian).
Bytes pack_row(const PngSpec& spec, int y, int x0, int dx, int count) {
    const int channels = channels_of(spec.color);
    const int depth = spec.bit_depth;
    const unsigned maxval = spec.color == PngColor::Palette ? (1u << std::min(depth, 8)) - 1 : (1u << depth) - 1;
    Bytes row((static_cast<std::size_t>(count) * channels * depth + 7) / 8, 0);
    std::size_t bit = 0;
    for (int i = 0; i < count; ++i) {
        for (int c = 0; c < channels; ++c) {
            const unsigned value = pattern_sample(x0 + i * dx, y, c, maxval);
            if (depth == 16) {
                row[bit / 8] = static_cast<std::uint8_t>(value >> 8);
                row[bit / 8 + 1] = static_cast<std::uint8_t>(value & 0xFF);
            } else {
                row[bit / 8] |= static_cast<std::uint8_t>(value << (8 - depth - bit % 8));
            }
            bit += depth;
        }
    }
    return row;
}

int paeth(int left, int up, int up_left) {
    const int p = left + up - up_left;
    const int to_left = std::abs(p - left), to_up = std::abs(p - up), to_up_left = std::abs(p - up_left);
    if (to_left <= to_up && to_left <= to_up_left) return left;
    return to_up <= to_up_left ? up : up_left;
}

// Appends the filter type byte and the filtered row. `prior` is the previous row of the same
// pass, unfiltered (all zeros for a pass's first row).
void append_filtered(Bytes& out, const Bytes& row, const Bytes& prior, int filter, int bytes_per_pixel) {
    out.push_back(static_cast<std::uint8_t>(filter));
    for (std::size_t i = 0; i < row.size(); ++i) {
        const int left = i >= static_cast<std::size_t>(bytes_per_pixel) ? row[i - bytes_per_pixel] : 0;
        const int up = prior[i];
        const int up_left = i >= static_cast<std::size_t>(bytes_per_pixel) ? prior[i - bytes_per_pixel] : 0;
        int predicted = 0;
        switch (filter) {
            case 1: predicted = left; break;
            case 2: predicted = up; break;
            case 3: predicted = (left + up) / 2; break;
            case 4: predicted = paeth(left, up, up_left); break;
        }
        out.push_back(static_cast<std::uint8_t>(row[i] - predicted));
    }
}

// The filtered image data: one pass, or Adam7's seven passes, each a small image of its own.
Bytes filtered_image_data(const PngSpec& spec) {
    struct Pass {
        int x0, y0, dx, dy;
    };
    const std::vector<Pass> passes = spec.interlaced
        ? std::vector<Pass>{{0, 0, 8, 8}, {4, 0, 8, 8}, {0, 4, 4, 8}, {2, 0, 4, 4}, {0, 2, 2, 4}, {1, 0, 2, 2}, {0, 1, 1, 2}}
        : std::vector<Pass>{{0, 0, 1, 1}};
    const int bits_per_pixel = channels_of(spec.color) * spec.bit_depth;
    const int bytes_per_pixel = std::max(1, bits_per_pixel / 8);
    Bytes data;
    int row_number = 0;
    for (const Pass& pass : passes) {
        const int columns = (spec.width - pass.x0 + pass.dx - 1) / pass.dx;
        const int rows = (spec.height - pass.y0 + pass.dy - 1) / pass.dy;
        if (columns <= 0 || rows <= 0) continue;  // an empty pass has no bytes at all
        Bytes prior((static_cast<std::size_t>(columns) * bits_per_pixel + 7) / 8, 0);
        for (int r = 0; r < rows; ++r) {
            const Bytes row = pack_row(spec, pass.y0 + r * pass.dy, pass.x0, pass.dx, columns);
            append_filtered(data, row, prior, spec.vary_filters ? row_number % 5 : 0, bytes_per_pixel);
            prior = row;
            ++row_number;
        }
    }
    return data;
}

std::string deflate_zlib(const Bytes& data, int level, bool fixed_huffman) {
    z_stream stream{};
    if (deflateInit2(&stream, level, Z_DEFLATED, 15, 8, fixed_huffman ? Z_FIXED : Z_DEFAULT_STRATEGY) != Z_OK)
        throw std::runtime_error("deflateInit2 failed");
    std::string out(deflateBound(&stream, data.size()), '\0');
    stream.next_in = const_cast<Bytef*>(data.data());
    stream.avail_in = static_cast<uInt>(data.size());
    stream.next_out = reinterpret_cast<Bytef*>(out.data());
    stream.avail_out = static_cast<uInt>(out.size());
    const int result = deflate(&stream, Z_FINISH);
    out.resize(stream.total_out);
    deflateEnd(&stream);
    if (result != Z_STREAM_END) throw std::runtime_error("deflate failed");
    return out;
}

}  // namespace

std::string encode_png(const PngSpec& spec) {
    std::string png = "\x89PNG\r\n\x1a\n";
    std::string header;
    put_u32(header, static_cast<std::uint32_t>(spec.width));
    put_u32(header, static_cast<std::uint32_t>(spec.height));
    header += static_cast<char>(spec.bit_depth);
    header += static_cast<char>(spec.color);
    header += '\0';  // compression method: deflate
    header += '\0';  // filter method: adaptive
    header += static_cast<char>(spec.interlaced ? 1 : 0);
    put_chunk(png, "IHDR", header);

    if (spec.color == PngColor::Palette) {
        const int entries = 1 << spec.bit_depth;
        std::string palette, alpha;
        for (int i = 0; i < entries; ++i) {
            for (int c = 0; c < 3; ++c) palette += static_cast<char>(pattern_sample(i, 1, c, 255));
            alpha += static_cast<char>(i * 255 / (entries - 1 > 0 ? entries - 1 : 1));
        }
        put_chunk(png, "PLTE", palette);
        if (spec.transparency) put_chunk(png, "tRNS", alpha);
    } else if (spec.transparency && (spec.color == PngColor::Grey || spec.color == PngColor::Rgb)) {
        // A colour key: the pattern's value at pixel (1, 0), so that some pixels match it.
        const unsigned maxval = (1u << spec.bit_depth) - 1;
        std::string key;
        for (int c = 0; c < channels_of(spec.color); ++c) {
            const unsigned value = pattern_sample(1, 0, c, maxval);
            key += static_cast<char>(value >> 8);
            key += static_cast<char>(value & 0xFF);
        }
        put_chunk(png, "tRNS", key);
    }
    if (spec.text_chunk) put_chunk(png, "tEXt", std::string("Comment\0clrender fuzz seed", 26));

    const std::string compressed = deflate_zlib(filtered_image_data(spec), spec.zlib_level, spec.fixed_huffman);
    const std::size_t chunks = static_cast<std::size_t>(std::max(1, spec.idat_chunks));
    const std::size_t piece = (compressed.size() + chunks - 1) / chunks;
    for (std::size_t start = 0; start < compressed.size(); start += piece)
        put_chunk(png, "IDAT", compressed.substr(start, piece));
    put_chunk(png, "IEND", "");
    return png;
}

// ---------------------------------------------------------------------------------------
// JPEG

std::string encode_jpeg(const JpegSpec& spec) {
    jpeg_compress_struct info{};
    jpeg_error_mgr errors{};
    info.err = jpeg_std_error(&errors);  // the seeds are fixed and valid: an error exits
    jpeg_create_compress(&info);
    unsigned char* buffer = nullptr;
    unsigned long size = 0;
    jpeg_mem_dest(&info, &buffer, &size);

    info.image_width = static_cast<JDIMENSION>(spec.width);
    info.image_height = static_cast<JDIMENSION>(spec.height);
    info.input_components = spec.components;
    info.in_color_space = spec.components == 1 ? JCS_GRAYSCALE : spec.components == 3 ? JCS_RGB : JCS_CMYK;
    jpeg_set_defaults(&info);
    jpeg_set_quality(&info, spec.quality, TRUE);
    if (spec.components == 3) {
        info.comp_info[0].h_samp_factor = spec.h_sampling;
        info.comp_info[0].v_samp_factor = spec.v_sampling;
    }
    if (spec.progressive) jpeg_simple_progression(&info);
    info.restart_in_rows = spec.restart_rows;
    info.optimize_coding = spec.optimize_huffman ? TRUE : FALSE;

    jpeg_start_compress(&info, TRUE);
    std::vector<JSAMPLE> row(static_cast<std::size_t>(spec.width) * spec.components);
    while (info.next_scanline < info.image_height) {
        const int y = static_cast<int>(info.next_scanline);
        for (int x = 0; x < spec.width; ++x)
            for (int c = 0; c < spec.components; ++c)
                row[static_cast<std::size_t>(x) * spec.components + c] = static_cast<JSAMPLE>(pattern_sample(x, y, c, 255));
        JSAMPROW rows[1] = {row.data()};
        jpeg_write_scanlines(&info, rows, 1);
    }
    jpeg_finish_compress(&info);
    jpeg_destroy_compress(&info);
    std::string jpeg(reinterpret_cast<const char*>(buffer), size);
    std::free(buffer);
    return jpeg;
}

// ---------------------------------------------------------------------------------------
// PPM

std::string encode_ppm(const PpmSpec& spec) {
    const std::string gap = spec.comments ? "\n# a comment, which may appear wherever whitespace may\n" : " ";
    std::string ppm = std::string(spec.ascii ? "P3" : "P6") + gap + std::to_string(spec.width) + gap +
                      std::to_string(spec.height) + gap + std::to_string(spec.maxval) + "\n";
    const unsigned maxval = static_cast<unsigned>(spec.maxval);
    for (int y = 0; y < spec.height; ++y) {
        for (int x = 0; x < spec.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                const unsigned value = pattern_sample(x, y, c, maxval);
                if (spec.ascii) {
                    ppm += std::to_string(value) + (c == 2 ? "\n" : " ");
                } else if (maxval > 255) {
                    ppm += static_cast<char>(value >> 8);
                    ppm += static_cast<char>(value & 0xFF);
                } else {
                    ppm += static_cast<char>(value);
                }
            }
        }
        if (spec.ascii && spec.comments) ppm += "# end of row " + std::to_string(y) + "\n";
    }
    return ppm;
}

// ---------------------------------------------------------------------------------------

std::vector<NamedFile> scene_images() {
    PngSpec transparent;  // RGBA with alpha 0 and 255 and values between
    PngSpec deep;
    deep.color = PngColor::Rgb;
    deep.bit_depth = 16;
    PngSpec grey;
    grey.color = PngColor::Grey;
    PngSpec palette;
    palette.color = PngColor::Palette;
    palette.bit_depth = 4;
    palette.transparency = true;
    JpegSpec photo;
    PpmSpec ascii;
    ascii.ascii = true;
    PpmSpec binary;
    return {
        {"tex.png", encode_png(transparent)},  {"tex16.png", encode_png(deep)},
        {"photo.jpg", encode_jpeg(photo)},     {"ascii.ppm", encode_ppm(ascii)},
        {"binary.ppm", encode_ppm(binary)},    {"backdrop.png", encode_png(grey)},
        {"checker.png", encode_png(palette)},  {"cutout.png", encode_png(transparent)},
        {"sign.ppm", encode_ppm(ascii)},
    };
}

}  // namespace clr::fuzz
