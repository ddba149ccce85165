#include "app/compared_image.h"

#include <optional>
#include <vector>

#include "core/errors.h"
#include "output/png_reader.h"
#include "scene/image_loader.h"

namespace clr {
namespace {

std::string size_text(long long width, long long height) {
    return std::to_string(width) + "x" + std::to_string(height);
}

SceneError unreadable(const std::string& path, const std::string& why) {
    return SceneError(path, "", "cannot read the image to compare with: " + why);
}

// The decoded pixels of a file whose header said it has the expected size.
Image decode(const std::string& path, const std::vector<unsigned char>& bytes, const ImageHeader& header, int width,
             int height) {
    if (header.format == "PNG") {
        PngHeader png;
        try {
            png = read_png_header(path);
            if (png.clrender_form) return read_png_pixels(path, width, height);
        } catch (const PngReadError& error) {
            throw unreadable(path, error.what());
        }
    }
    try {
        return *load_image_from_bytes(bytes, path);
    } catch (const ImageError& error) {
        throw unreadable(path, error.what());
    }
}

}  // namespace

Image read_compared_image(const std::string& path, int width, int height) {
    std::vector<unsigned char> bytes;
    try {
        bytes = read_image_file(path);
    } catch (const ImageError& error) {
        throw unreadable(path, error.what());
    }
    const std::optional<ImageHeader> header = read_image_header(bytes);
    if (!header) {
        try {
            load_image_from_bytes(bytes, path);  // says why the header cannot be read
        } catch (const ImageError& error) {
            throw unreadable(path, error.what());
        }
        throw unreadable(path, "its header cannot be read");
    }
    if (header->width != width || header->height != height)
        throw SceneError(path, "", "the image is " + size_text(header->width, header->height) + ", the render is " +
                                       size_text(width, height) + " (--size " +
                                       size_text(header->width, header->height) + " renders at the image's size)");
    Image image = decode(path, bytes, *header, width, height);
    image.path = path;
    if (image.width != width || image.height != height)  // the file changed between its header and its pixels
        throw unreadable(path, "the file changed while it was read");
    return image;
}

}  // namespace clr
