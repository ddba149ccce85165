// PNG files whose transparency is a tRNS chunk rather than an alpha channel, encoded with
// libpng: an RGB image with one transparent colour (a colour key), and a palette image with
// an alpha per palette entry. What clrender's loader must decode to alpha 0 (or the entry's
// alpha) exactly where the chunk says.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace clr::testing {

using Rgb = std::array<std::uint8_t, 3>;

// An 8-bit RGB PNG of width x height texels, rgb[row * width + col], whose texels of colour
// `key` are transparent.
std::vector<unsigned char> rgb_png_with_colour_key(int width, int height, const std::vector<Rgb>& rgb, const Rgb& key);

// An 8-bit palette PNG whose texel (col, row) is palette entry indices[row * width + col], and
// entry i has alpha alphas[i] (entries past alphas.size() are opaque).
std::vector<unsigned char> palette_png_with_alphas(int width, int height, const std::vector<std::uint8_t>& indices,
                                                   const std::vector<Rgb>& palette,
                                                   const std::vector<std::uint8_t>& alphas);

}  // namespace clr::testing
