// Frame output: PNG through stb_image_write, PPM P6 by hand (a header and the bytes). Both go
// through AtomicFile, and both are deterministic: the same image always gives the same bytes.
#include "output/image_writer.h"

#include <stb_image_write.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "core/errors.h"
#include "output/atomic_file.h"

namespace clr {
namespace {

std::vector<std::uint8_t> rgb_without_alpha(const Image& image) {
    std::vector<std::uint8_t> rgb;
    rgb.reserve(image.rgba.size() / 4 * 3);
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        rgb.insert(rgb.end(), image.rgba.begin() + i, image.rgba.begin() + i + 3);
    }
    return rgb;
}

// stb_image_write calls this with each piece of the encoded PNG. An exception must not
// unwind through stb's C code, so a failed write is kept and rethrown once stb returns.
struct PngSink {
    AtomicFile& file;
    std::exception_ptr failure;

    static void write(void* context, void* data, int size) {
        auto& sink = *static_cast<PngSink*>(context);
        if (sink.failure) return;
        try {
            sink.file.write(data, static_cast<std::size_t>(size));
        } catch (...) {
            sink.failure = std::current_exception();
        }
    }
};

void write_png(AtomicFile& file, const Image& image) {
    const std::vector<std::uint8_t> rgb = rgb_without_alpha(image);
    PngSink sink{file, nullptr};
    const int ok = stbi_write_png_to_func(&PngSink::write, &sink, image.width, image.height, 3, rgb.data(),
                                          image.width * 3);
    if (sink.failure) std::rethrow_exception(sink.failure);
    if (!ok) throw OutputError(file.final_path() + ": the PNG encoder failed");
}

void write_ppm(AtomicFile& file, const Image& image) {
    const std::string header = "P6\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n255\n";
    file.write(header.data(), header.size());
    const std::vector<std::uint8_t> rgb = rgb_without_alpha(image);
    file.write(rgb.data(), rgb.size());
}

void check_image(const std::string& path, const Image& image) {
    // stb_image_write takes the row length in bytes as an int.
    const bool size_ok = image.width > 0 && image.height > 0 && image.width <= INT_MAX / 3 &&
                         image.rgba.size() == static_cast<std::size_t>(image.width) * image.height * 4;
    if (!size_ok) {
        throw OutputError(path + ": cannot write a " + std::to_string(image.width) + "x" +
                          std::to_string(image.height) + " image with " + std::to_string(image.rgba.size()) +
                          " bytes of RGBA data");
    }
}

}  // namespace

ImageFormat image_format_for(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".png") return ImageFormat::Png;
    if (extension == ".ppm") return ImageFormat::Ppm;
    const std::string problem = extension.empty() ? "no file extension" : "unsupported extension '" + extension + "'";
    throw UsageError(path + ": " + problem + " for an image (supported: .png, .ppm)");
}

void write_image(const std::string& path, const Image& image) {
    const ImageFormat format = image_format_for(path);
    check_image(path, image);
    AtomicFile file(path);
    if (format == ImageFormat::Png) {
        write_png(file, image);
    } else {
        write_ppm(file, image);
    }
    file.commit();
}

}  // namespace clr
