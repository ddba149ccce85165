// Reads back the PNGs that clrender writes, with libpng: what a file says it is (its size,
// alpha channel and text chunks, from the chunks before the pixel data: cheap), and its pixels.
// --resume and --assemble compare the description with the run's; --join pastes tiles
// (docs/command-line.md, PNG metadata; Joining tiles).
#pragma once

#include <stdexcept>
#include <string>

#include "core/image.h"
#include "output/image_writer.h"

namespace clr {

// Why a PNG cannot be read: one line (not a PNG, truncated, damaged, cannot be opened).
class PngReadError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct PngHeader {
    int width = 0, height = 0;
    bool alpha = false;        // RGBA (clrender's --alpha PNGs) rather than RGB
    bool clrender_form = false;  // 8-bit RGB or RGBA, as clrender writes every PNG
    ImageText text;            // tEXt (and zTXt, iTXt) chunks before the pixel data, in file order
};

// Reads the chunks before the pixel data, and checks that the file ends with its IEND chunk
// (a file cut short, by a copy or a full disk, is refused without decoding it). Damage inside
// the pixel data is found only by read_png_pixels. Throws PngReadError; never reads a file
// that is not a regular file (a FIFO would block).
PngHeader read_png_header(const std::string& path);

// Decodes the whole file (every chunk's CRC and the compressed data are checked) into 8-bit
// RGBA, alpha 255 for an RGB file. Only clrender's form, and only an image of
// `width` x `height` (checked before any pixel memory is taken): the caller knows what size to
// expect. Throws PngReadError.
Image read_png_pixels(const std::string& path, int width, int height);

}  // namespace clr
