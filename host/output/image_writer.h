// Writes rendered frames: PNG, PPM (binary P6) or OpenEXR (exr_writer.h), chosen by the path's
// extension, always atomically (see atomic_file.h).
#pragma once

#include <memory>
#include <string>

#include "core/image.h"
#include "output/atomic_file.h"

namespace clr {

enum class ImageFormat { Png, Ppm, Exr };

// The format for `path` from its extension (".png", ".ppm", ".exr", any case). Throws UsageError for
// any other extension, naming the path and the supported ones.
ImageFormat image_format_for(const std::string& path);

// Writes the RGBA image (alpha is dropped unless image.write_alpha: then a PNG is RGBA; an EXR
// writes image.linear, with A when image.write_alpha). Throws OutputError
// naming the path when the file cannot be written; nothing is left under `path` then.
void write_image(const std::string& path, const Image& image);

// Writes the image completely under a temporary name and returns the file, not yet renamed
// into place (see staged_outputs.h). Throws OutputError as write_image does.
std::unique_ptr<AtomicFile> write_image_uncommitted(const std::string& path, const Image& image);

}  // namespace clr
