// Frame output: PNG through libpng, PPM P6 by hand (a header and the bytes). Both go
// through AtomicFile, and both are deterministic: the same image always gives the same bytes.
#include "output/image_writer.h"

#include <png.h>

#include <csetjmp>
#include <new>

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
#include "output/exr_writer.h"
#include "output/file_extension.h"
#include "output/png_pixel_data.h"

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

// PNG through libpng, set for speed: RGB, 8 bits, every row with the "Up" filter, the rows
// deflated by ISA-L's igzip (png_pixel_data.h), which libpng writes as IDAT chunks beside its
// own header, colour and text chunks. libpng's zlib at level 1 with run-length matching took
// most of a 1080p frame's writing time; igzip takes a quarter of that or less, for files as
// small (docs/benchmarks.md, Figures behind design choices).
//
// libpng reports errors by longjmp, so encoding runs in a function with nothing to unwind
// into memory, and the file is written afterwards (where an OutputError may be thrown). libpng
// never touches the disk itself: every short write, ENOSPC or failed fsync surfaces through
// AtomicFile's checked write() and complete().
struct PngOutput {
    std::vector<std::uint8_t> bytes;
    bool out_of_memory = false;
};

void append_png_bytes(png_structp png, png_bytep data, png_size_t size) {
    auto* output = static_cast<PngOutput*>(png_get_io_ptr(png));
    try {
        output->bytes.insert(output->bytes.end(), data, data + size);
    } catch (const std::bad_alloc&) {
        output->out_of_memory = true;
    }
    if (output->out_of_memory) png_error(png, "out of memory");
}

void flush_png(png_structp) {}

// tEXt holds Latin-1: anything but printable ASCII (a UTF-8 file name, a control character)
// is written as \xNN, so a reader shows exactly the bytes it stands for.
std::string text_chunk_safe(const std::string& text) {
    static const char* const digits = "0123456789ABCDEF";
    std::string safe;
    for (unsigned char c : text) {
        if (c >= 0x20 && c < 0x7F && c != '\\') {
            safe += static_cast<char>(c);
        } else {
            safe += {'\\', 'x', digits[c >> 4], digits[c & 15]};
        }
    }
    return safe;
}

// What libpng's text structures point to, kept until the PNG is written. Owned by the caller
// of setjmp, so that a longjmp out of libpng skips no destructor.
struct PngTextStorage {
    std::vector<std::string> strings;
    std::vector<png_text> chunks;
};

// The chunks that say what the pixels are: sRGB colours (rendered for an sRGB display, so
// colour-managed viewers show them unchanged) and the caller's text.
void set_png_description(png_structp png, png_infop info, const ImageText& text, PngTextStorage& storage) {
    png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    if (text.empty()) return;
    for (const auto& [keyword, value] : png_text_as_written(text)) {
        storage.strings.push_back(keyword);
        storage.strings.push_back(value);
    }
    storage.chunks.resize(text.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
        storage.chunks[i].compression = PNG_TEXT_COMPRESSION_NONE;
        storage.chunks[i].key = const_cast<png_charp>(storage.strings[2 * i].c_str());
        storage.chunks[i].text = const_cast<png_charp>(storage.strings[2 * i + 1].c_str());
        storage.chunks[i].text_length = storage.strings[2 * i + 1].size();
    }
    png_set_text(png, info, storage.chunks.data(), static_cast<int>(storage.chunks.size()));  // libpng copies them
}

// IDAT chunks of at most this many bytes: far below PNG's 2^31 limit for any image, and a
// reader's buffer for one stays small.
constexpr std::size_t kMaxDataChunk = std::size_t{1} << 20;

void write_pixel_chunks(png_structp png, const std::vector<std::uint8_t>& pixel_data) {
    static const png_byte kIdat[5] = "IDAT";
    for (std::size_t offset = 0; offset < pixel_data.size(); offset += kMaxDataChunk)
        png_write_chunk(png, kIdat, pixel_data.data() + offset, std::min(kMaxDataChunk, pixel_data.size() - offset));
}

// Returns libpng's message, or an empty string when `output` holds the whole PNG.
// `pixel_data` is png_pixel_data(image), made before: nothing in here may throw.
std::string encode_png(const Image& image, const ImageText& text, const std::vector<std::uint8_t>& pixel_data,
                       PngOutput& output) {
    PngTextStorage text_storage;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        return "cannot start libpng";
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return output.out_of_memory ? "out of memory" : "libpng failed";
    }
    png_set_write_fn(png, &output, append_png_bytes, flush_png);
    const int color_type = image.write_alpha ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_RGB;  // --alpha: straight alpha
    png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8,
                 color_type, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    set_png_description(png, info, text, text_storage);
    png_write_info(png, info);  // signature, IHDR, sRGB, tEXt
    write_pixel_chunks(png, pixel_data);
    // png_write_end() would refuse: libpng did not write the IDAT chunks itself.
    static const png_byte kIend[5] = "IEND";
    png_write_chunk(png, kIend, nullptr, 0);
    png_destroy_write_struct(&png, &info);
    return "";
}

// The whole PNG in memory; `name` says in messages what it was for.
std::vector<std::uint8_t> encode_png_bytes(const std::string& name, const Image& image, const ImageText& text) {
    std::vector<std::uint8_t> pixel_data;
    try {
        pixel_data = png_pixel_data(image);
    } catch (const std::bad_alloc&) {
        throw;  // out of memory has its own exit code
    } catch (const std::exception& error) {
        throw OutputError(name + ": the PNG encoder failed (" + error.what() + ")");
    }
    PngOutput output;
    const std::string problem = encode_png(image, text, pixel_data, output);
    if (!problem.empty()) throw OutputError(name + ": the PNG encoder failed (" + problem + ")");
    return std::move(output.bytes);
}

void write_png(AtomicFile& file, const Image& image, const ImageText& text) {
    const std::vector<std::uint8_t> bytes = encode_png_bytes(file.final_path(), image, text);
    file.write(bytes.data(), bytes.size());
}

void write_ppm(AtomicFile& file, const Image& image) {
    const std::string header = "P6\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n255\n";
    file.write(header.data(), header.size());
    const std::vector<std::uint8_t> rgb = rgb_without_alpha(image);
    file.write(rgb.data(), rgb.size());
}

void check_image(const std::string& path, const Image& image) {
    // Keeps row and image sizes far from overflowing int.
    const bool size_ok = image.width > 0 && image.height > 0 && image.width <= INT_MAX / 3 &&
                         image.rgba.size() == static_cast<std::size_t>(image.width) * image.height * 4;
    if (!size_ok) {
        throw OutputError(path + ": cannot write a " + std::to_string(image.width) + "x" +
                          std::to_string(image.height) + " image with " + std::to_string(image.rgba.size()) +
                          " bytes of RGBA data");
    }
}

}  // namespace

std::vector<std::uint8_t> png_bytes(const Image& image, const ImageText& text) {
    return encode_png_bytes("PNG in memory", image, text);
}

ImageText png_text_as_written(const ImageText& text) {
    ImageText written;
    for (const auto& [keyword, value] : text) written.emplace_back(text_chunk_safe(keyword).substr(0, 79), text_chunk_safe(value));
    return written;
}

ImageFormat image_format_for(const std::string& path) {
    const std::string extension = lowercase_extension(path);
    if (extension == ".png") return ImageFormat::Png;
    if (extension == ".ppm") return ImageFormat::Ppm;
    if (extension == ".exr") return ImageFormat::Exr;
    const std::string problem = extension.empty() ? "no file extension" : "unsupported extension '" + extension + "'";
    throw UsageError(path + ": " + problem + " for an image (supported: .png, .ppm, .exr)");
}

std::unique_ptr<AtomicFile> write_image_uncommitted(const std::string& path, const Image& image, const ImageText& text) {
    const ImageFormat format = image_format_for(path);
    check_image(path, image);
    auto file = std::make_unique<AtomicFile>(path);
    if (format == ImageFormat::Png) {
        write_png(*file, image, text);
    } else if (format == ImageFormat::Exr) {
        const std::vector<char> bytes = encode_exr(path, image);
        file->write(bytes.data(), bytes.size());
    } else {
        write_ppm(*file, image);
    }
    file->complete();
    return file;
}

void write_image(const std::string& path, const Image& image, const ImageText& text) {
    write_image_uncommitted(path, image, text)->commit();
}

}  // namespace clr
