#include "support/keyed_png.h"

#include <png.h>

#include <stdexcept>

namespace clr::testing {
namespace {

void append_bytes(png_structp png, png_bytep data, png_size_t size) {
    auto* out = static_cast<std::vector<unsigned char>*>(png_get_io_ptr(png));
    out->insert(out->end(), data, data + size);
}

void no_flush(png_structp) {}

// Encodes rows of `bytes_per_texel` bytes a texel; `chunks` sets PLTE and tRNS on the info.
template <typename SetChunks>
std::vector<unsigned char> encode(int width, int height, int color_type, int bytes_per_texel,
                                  const std::vector<std::uint8_t>& samples, SetChunks chunks) {
    std::vector<unsigned char> out;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) throw std::runtime_error("libpng: no write struct");
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        throw std::runtime_error("libpng: encoding failed");
    }
    png_set_write_fn(png, &out, append_bytes, no_flush);
    png_set_IHDR(png, info, width, height, 8, color_type, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    chunks(png, info);
    png_write_info(png, info);
    for (int row = 0; row < height; ++row)
        png_write_row(png, const_cast<png_bytep>(samples.data() + static_cast<std::size_t>(row) * width * bytes_per_texel));
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return out;
}

}  // namespace

std::vector<unsigned char> rgb_png_with_colour_key(int width, int height, const std::vector<Rgb>& rgb, const Rgb& key) {
    std::vector<std::uint8_t> samples;
    for (const Rgb& texel : rgb) samples.insert(samples.end(), texel.begin(), texel.end());
    return encode(width, height, PNG_COLOR_TYPE_RGB, 3, samples, [&](png_structp png, png_infop info) {
        png_color_16 colour{};
        colour.red = key[0];
        colour.green = key[1];
        colour.blue = key[2];
        png_set_tRNS(png, info, nullptr, 0, &colour);
    });
}

std::vector<unsigned char> palette_png_with_alphas(int width, int height, const std::vector<std::uint8_t>& indices,
                                                   const std::vector<Rgb>& palette,
                                                   const std::vector<std::uint8_t>& alphas) {
    return encode(width, height, PNG_COLOR_TYPE_PALETTE, 1, indices, [&](png_structp png, png_infop info) {
        std::vector<png_color> entries;
        for (const Rgb& c : palette) entries.push_back({c[0], c[1], c[2]});
        png_set_PLTE(png, info, entries.data(), static_cast<int>(entries.size()));
        std::vector<png_byte> trns(alphas.begin(), alphas.end());
        png_set_tRNS(png, info, trns.data(), static_cast<int>(trns.size()), nullptr);
    });
}

}  // namespace clr::testing
