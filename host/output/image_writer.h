// Writes rendered frames: PNG, PPM (binary P6) or OpenEXR (exr_writer.h), chosen by the path's
// extension, always atomically (see atomic_file.h).
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/image.h"
#include "output/atomic_file.h"

namespace clr {

enum class ImageFormat { Png, Ppm, Exr };

// The format for `path` from its extension (".png", ".ppm", ".exr", any case). Throws UsageError for
// any other extension, naming the path and the supported ones.
ImageFormat image_format_for(const std::string& path);

// What an image shows, as (keyword, text) pairs in order: a PNG stores each as a tEXt chunk
// (bytes outside printable ASCII in the text are written as \xNN, since tEXt is Latin-1); PPM
// and EXR have no place for it here. Keywords are 1 to 79 printable ASCII characters.
using ImageText = std::vector<std::pair<std::string, std::string>>;

// `text` as a PNG holds it (the \xNN escapes, keywords cut to 79 characters): what a reader of
// the file finds, to compare with (png_reader.h).
ImageText png_text_as_written(const ImageText& text);

// Writes the RGBA image (alpha is dropped unless image.write_alpha: then a PNG is RGBA; an EXR
// writes image.linear, with A when image.write_alpha). A PNG, RGB or RGBA, is marked as sRGB
// (an sRGB chunk, perceptual intent) and carries `text`. Throws OutputError naming the path
// when the file cannot be written; nothing is left under `path` then.
void write_image(const std::string& path, const Image& image, const ImageText& text = {});

// The bytes of the PNG file write_image() writes for `image`, in memory (`clrender view` sends
// them to the browser). Throws OutputError as write_image does.
std::vector<std::uint8_t> png_bytes(const Image& image, const ImageText& text = {});

// Writes the image completely under a temporary name and returns the file, not yet renamed
// into place (see staged_outputs.h). Throws OutputError as write_image does.
std::unique_ptr<AtomicFile> write_image_uncommitted(const std::string& path, const Image& image,
                                                    const ImageText& text = {});

}  // namespace clr
