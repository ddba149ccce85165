// Reads billboard images: PNG (8- and 16-bit, with or without alpha), JPEG, PPM P6 and
// PPM P3 (ASCII, with '#' comments). Every image becomes 8-bit RGBA
// (docs/scene-format.md, Conventions: Billboards).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/image.h"

namespace clr {

// Why an image could not be read. The scene loader adds the scene file and JSON location.
class ImageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Largest image file read. stb_image takes a length as an int, and no sensible billboard
// image comes near: an 8192 x 8192 PPM with 16-bit samples is 384 MiB.
constexpr std::uint64_t kMaxImageFileBytes = std::uint64_t(1) << 30;

// Reads the image at `path`; the format is taken from the file's content, not its name.
// Throws ImageError with a one-line reason (missing, unreadable, corrupt, unsupported).
std::shared_ptr<const Image> load_image(const std::string& path);

// load_image in two steps, for a caller that needs the file's bytes too (the image cache
// hashes them): the whole file, with load_image's errors for a file that is missing,
// unreadable, empty or too large; then the image those bytes hold, with its errors for
// content. `path` only names the image.
std::vector<unsigned char> read_image_file(const std::string& path);
std::shared_ptr<const Image> load_image_from_bytes(const std::vector<unsigned char>& bytes, const std::string& path);

// An image's size as its header gives it, and the bytes decoding it allocates at its peak:
// for PNG, stb_image's two RGBA buffers (the raw samples and its output, of 16-bit samples
// for a 16-bit PNG), 8 bytes a pixel or 16 for a 16-bit PNG; for JPEG, libjpeg-turbo's RGBA
// result and the coefficients of a progressive file, 4 + 2 x the components' samples a pixel
// (7 for 4:2:0 colour); for PPM, which is decoded straight into the 8-bit RGBA result, 4.
struct ImageHeader {
    long long width = 0, height = 0;
    bool sixteen_bit = false;
    std::uint64_t decoding_bytes = 0;
    std::string format = {};     // "PNG", "JPEG" or "PPM"
    bool alpha_channel = false;  // a PNG with alpha or a tRNS chunk: texels may be transparent
};

// The header of the image in `bytes`, read without decoding anything; nullopt when the
// header cannot be read or claims more than one image may hold (load_image_from_bytes then
// says why).
std::optional<ImageHeader> read_image_header(const std::vector<unsigned char>& bytes);

// A stand-in for an image that cannot be read, used only when the user asks for
// placeholders: an opaque 8x8 magenta and grey checkerboard, unmistakable in a render.
std::shared_ptr<const Image> make_placeholder_image(const std::string& path_it_replaces);

}  // namespace clr
