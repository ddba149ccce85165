// JPEG decoding with libjpeg-turbo (docs/scene-format.md, Images). libjpeg reports
// errors by longjmp; everything here keeps that inside C-style code and turns it into an
// ImageError, so that no C++ object is skipped and nothing leaks.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/image.h"

namespace clr {

// Decodes the JPEG in `bytes` into `image` as 8-bit RGBA (alpha 255): grey is expanded,
// CMYK converted as stb_image and Photoshop do (Adobe's inverted CMYK). `check_size` is called
// with the header's width and height before any pixel memory is allocated, and may throw.
// Throws ImageError naming what is wrong or unsupported.
void decode_jpeg(const std::vector<unsigned char>& bytes, Image& image,
                 void (*check_size)(long long width, long long height));

// libjpeg-turbo's version number ("2001005" for 2.1.5) and a function of the library, for the
// decoded-image cache's key: which build decodes JPEG.
std::string jpeg_decoder_version();
void* jpeg_decoder_entry_point();

}  // namespace clr
