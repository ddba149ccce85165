// Image input. PNG is decoded by stb_image, JPEG by libjpeg-turbo (scene/jpeg_decoder.h), PPM
// (P3 and P6) by the small reader below, for the reasons given at read_ppm(). The format is
// taken from the file's first bytes.
#include "scene/image_loader.h"

#include <stb_image.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

#include "core/printable_text.h"
#include "scene/bounded_file.h"
#include "scene/jpeg_checks.h"
#include "scene/jpeg_decoder.h"
#include "scene/limits.h"

namespace clr {
namespace {

using Bytes = std::vector<unsigned char>;

constexpr int kRgba = 4;

// ---------------------------------------------------------------------------------------
// Reading the file and recognising its format

Bytes read_whole_file(const std::string& path) {
    std::error_code error;
    const auto status = std::filesystem::status(path, error);
    if (status.type() == std::filesystem::file_type::not_found) throw ImageError("no such file");
    if (error) throw ImageError("cannot read: " + error.message());
    if (status.type() != std::filesystem::file_type::regular) throw ImageError("not a file");

    // Checked again on the open file (the path may have changed meanwhile), and read no
    // further than the limit: a sparse or endless file costs nothing.
    Bytes bytes;
    try {
        bytes = read_bounded_bytes(path, kMaxImageFileBytes);
    } catch (const BoundedFileError& error) {
        throw ImageError(error.what());
    }
    if (bytes.empty()) throw ImageError("empty file");
    return bytes;
}

enum class FileFormat { Png, Jpeg, PpmAscii, PpmBinary };

bool starts_with(const Bytes& bytes, std::initializer_list<unsigned char> magic) {
    return bytes.size() >= magic.size() && std::equal(magic.begin(), magic.end(), bytes.begin());
}

bool is_ppm_whitespace(unsigned char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

FileFormat detect_format(const Bytes& bytes) {
    if (starts_with(bytes, {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'})) return FileFormat::Png;
    if (starts_with(bytes, {0xFF, 0xD8, 0xFF})) return FileFormat::Jpeg;
    // Netpbm: "P" and a digit, then whitespace (or a comment) before the width.
    if (bytes.size() >= 3 && bytes[0] == 'P' && (is_ppm_whitespace(bytes[2]) || bytes[2] == '#')) {
        if (bytes[1] == '3') return FileFormat::PpmAscii;
        if (bytes[1] == '6') return FileFormat::PpmBinary;
        if (bytes[1] >= '1' && bytes[1] <= '7') {
            throw ImageError(std::string("unsupported image format: Netpbm P") + char(bytes[1]) +
                             " (only PPM P3 and P6 are read)");
        }
    }
    throw ImageError("unsupported image format (PNG, JPEG, PPM P3 and P6 are read)");
}

// The largest image read, in pixels, is kMaxImagePixels (scene/limits.h): as large as the
// largest frame clrender renders (8192 x 8192, 256 MiB as RGBA), more than any billboard
// needs. A compressed file can claim a huge raster in a few bytes (the image fuzzer found a
// 1.6 KB JPEG that decodes to 49680 x 255 texels, and the decoders accept up to 2 GiB of
// pixels), so the size is checked from the header, before anything is allocated or decoded.
// PPM needs no such limit: its raster is stored uncompressed, so a header larger than the
// file is refused as truncated.
// Compared by division: a header's two 32-bit sides can multiply past any 64-bit integer. A
// side of 0 is left to the decoder, which names it.
void check_pixel_count(long long width, long long height, const char* format_name) {
    if (width <= 0 || height <= 0 || width <= kMaxImagePixels / height) return;
    throw ImageError(std::string(format_name) + " image of " + std::to_string(width) + " x " + std::to_string(height) +
                     " pixels is larger than the limit of " + std::to_string(kMaxImagePixels) + " pixels (" +
                     max_square_image_text() + ")");
}

std::uint32_t big_endian_32(const Bytes& bytes, std::size_t at) {
    return (std::uint32_t(bytes[at]) << 24) | (std::uint32_t(bytes[at + 1]) << 16) | (std::uint32_t(bytes[at + 2]) << 8) |
           bytes[at + 3];
}

// A sample in 0..maxval as a byte in 0..255, rounded to nearest (halves up).
std::uint8_t scale_to_byte(std::uint32_t sample, std::uint32_t maxval) {
    return static_cast<std::uint8_t>((sample * 255 + maxval / 2) / maxval);
}

// ---------------------------------------------------------------------------------------
// PNG through stb_image, JPEG through libjpeg-turbo

struct StbFree {
    void operator()(void* pixels) const { stbi_image_free(pixels); }
};

ImageError stb_error(const char* format_name) {
    const char* reason = stbi_failure_reason();
    return ImageError(std::string("corrupt ") + format_name + ": " + printable(reason ? reason : "unknown error"));
}

// stb refuses a PNG larger than it can hold (2^30 bytes of samples) as an "unknown image
// type" after trying every other format on it; the size is in IHDR, the first chunk, so it
// is checked here, where the message can say what is wrong.
void check_png_size(const Bytes& bytes) {
    constexpr std::size_t kIhdrType = 12, kWidth = 16, kHeight = 20;
    if (bytes.size() < kHeight + 4 || !std::equal(bytes.begin() + kIhdrType, bytes.begin() + kWidth, "IHDR")) return;
    check_pixel_count(big_endian_32(bytes, kWidth), big_endian_32(bytes, kHeight), "PNG");
}

// A JPEG of a kind libjpeg-turbo does not decode, or too large, is named from its frame header,
// rather than by libjpeg's message ("Unsupported JPEG process: SOF type 0xc3", or one about
// the missing data of a file that is mostly header). libjpeg checks the size again from the
// header it reads itself, before it allocates anything for pixels.
void decode_jpeg_file(const Bytes& bytes, Image& image) {
    if (const std::optional<JpegFrame> frame = find_jpeg_frame(bytes)) {
        check_jpeg_frame_is_supported(*frame);
        check_pixel_count(frame->width, frame->height, "JPEG");
    }
    decode_jpeg(bytes, image, [](long long width, long long height) { check_pixel_count(width, height, "JPEG"); });
}

// Decodes to 8-bit RGBA; stb fills in alpha 255 for images without alpha, and expands grey.
void decode_with_stb(const Bytes& bytes, const char* format_name, Image& image) {
    const int length = static_cast<int>(bytes.size());
    int channels_in_file = 0;
    // The header alone gives the size (stb reads no pixels for this).
    int width = 0, height = 0;
    if (!stbi_info_from_memory(bytes.data(), length, &width, &height, &channels_in_file)) throw stb_error(format_name);
    check_pixel_count(width, height, format_name);
    // 16-bit files are read at full depth and rounded here: stbi_load would truncate
    // (value >> 8), which is up to one step darker than round(value * 255 / 65535).
    if (stbi_is_16_bit_from_memory(bytes.data(), length)) {
        std::unique_ptr<std::uint16_t, StbFree> pixels(stbi_load_16_from_memory(
            bytes.data(), length, &image.width, &image.height, &channels_in_file, kRgba));
        if (!pixels) throw stb_error(format_name);
        const std::size_t count = static_cast<std::size_t>(image.width) * image.height * kRgba;
        image.rgba.resize(count);
        for (std::size_t i = 0; i < count; ++i) image.rgba[i] = scale_to_byte(pixels.get()[i], 65535);
        return;
    }
    std::unique_ptr<unsigned char, StbFree> pixels(
        stbi_load_from_memory(bytes.data(), length, &image.width, &image.height, &channels_in_file, kRgba));
    if (!pixels) throw stb_error(format_name);
    const std::size_t count = static_cast<std::size_t>(image.width) * image.height * kRgba;
    image.rgba.assign(pixels.get(), pixels.get() + count);
}

// ---------------------------------------------------------------------------------------
// PPM, P3 and P6
//
// Hand-written because stb_image cannot do the job: it does not read P3 (ASCII) at all, and
// its P6 reader (stb_image 2.27, as packaged by Debian) returns uninitialised pixels instead
// of an error when the raster is cut short, does not scale samples whose maxval is not 255,
// and reads 16-bit samples in the host's byte order instead of big-endian. Both variants
// share the header, so one reader serves both, and the binary raster takes a few lines.

// Reads the unsigned decimal numbers of a Netpbm header (and of a P3 raster), separated by
// whitespace, where '#' starts a comment that runs to the end of its line. Netpbm allows a
// comment wherever whitespace may appear.
class PpmNumberReader {
public:
    PpmNumberReader(const Bytes& bytes, std::size_t start) : bytes_(bytes), pos_(start) {}

    // The next number; `what` names it in errors ("width", "sample", ...). Stops right
    // after the last digit, so a P6 reader can find the single whitespace byte after maxval.
    std::uint32_t next(const char* what, const char* error_at_end) {
        skip_whitespace_and_comments();
        if (pos_ == bytes_.size()) throw ImageError(error_at_end);
        if (!is_digit(bytes_[pos_])) throw ImageError(std::string("corrupt PPM: expected a number for ") + what);
        std::uint64_t value = 0;
        for (; pos_ < bytes_.size() && is_digit(bytes_[pos_]); ++pos_) {
            value = value * 10 + (bytes_[pos_] - '0');
            if (value > kLargestNumber) throw ImageError(std::string("corrupt PPM: ") + what + " is too large");
        }
        if (pos_ < bytes_.size() && !is_ppm_whitespace(bytes_[pos_]) && bytes_[pos_] != '#') {
            throw ImageError(std::string("corrupt PPM: unexpected character after ") + what);
        }
        return static_cast<std::uint32_t>(value);
    }

    std::size_t position() const { return pos_; }

private:
    // Larger than any valid maxval (65535) and any width or height we could hold.
    static constexpr std::uint64_t kLargestNumber = 1u << 30;

    static bool is_digit(unsigned char c) { return c >= '0' && c <= '9'; }

    void skip_whitespace_and_comments() {
        while (pos_ < bytes_.size()) {
            if (bytes_[pos_] == '#') {
                while (pos_ < bytes_.size() && bytes_[pos_] != '\n' && bytes_[pos_] != '\r') ++pos_;
            } else if (is_ppm_whitespace(bytes_[pos_])) {
                ++pos_;
            } else {
                return;
            }
        }
    }

    const Bytes& bytes_;
    std::size_t pos_;
};

struct PpmHeader {
    std::uint32_t width = 0, height = 0, maxval = 0;
    std::uint64_t sample_count() const { return std::uint64_t(width) * height * 3; }
};

PpmHeader read_ppm_header(PpmNumberReader& numbers) {
    const char* truncated = "truncated PPM header";
    PpmHeader header;
    header.width = numbers.next("width", truncated);
    header.height = numbers.next("height", truncated);
    header.maxval = numbers.next("maxval", truncated);
    if (header.width == 0 || header.height == 0) throw ImageError("corrupt PPM: zero width or height");
    if (header.maxval == 0 || header.maxval > 65535) {
        throw ImageError("corrupt PPM: maxval " + std::to_string(header.maxval) + " is not in 1..65535");
    }
    return header;
}

void check_sample(std::uint32_t sample, const PpmHeader& header) {
    if (sample > header.maxval) {
        throw ImageError("corrupt PPM: sample " + std::to_string(sample) + " exceeds maxval " +
                         std::to_string(header.maxval));
    }
}

void allocate_opaque(const PpmHeader& header, Image& image) {
    image.width = static_cast<int>(header.width);
    image.height = static_cast<int>(header.height);
    image.rgba.assign(static_cast<std::size_t>(header.width) * header.height * kRgba, 255);
}

void read_ppm_ascii_raster(PpmNumberReader& numbers, const PpmHeader& header, Image& image) {
    allocate_opaque(header, image);
    for (std::uint64_t i = 0; i < header.sample_count(); ++i) {
        const std::uint32_t sample = numbers.next("sample", "truncated PPM data");
        check_sample(sample, header);
        image.rgba[i / 3 * kRgba + i % 3] = scale_to_byte(sample, header.maxval);
    }
}

void read_ppm_binary_raster(const Bytes& bytes, std::size_t start, const PpmHeader& header, Image& image) {
    const std::uint64_t bytes_per_sample = header.maxval > 255 ? 2 : 1;  // big-endian when 2
    if (bytes.size() - start < header.sample_count() * bytes_per_sample) throw ImageError("truncated PPM data");
    allocate_opaque(header, image);
    const unsigned char* raster = bytes.data() + start;
    for (std::uint64_t i = 0; i < header.sample_count(); ++i) {
        const std::uint32_t sample =
            bytes_per_sample == 2 ? (std::uint32_t(raster[2 * i]) << 8) | raster[2 * i + 1] : raster[i];
        check_sample(sample, header);
        image.rgba[i / 3 * kRgba + i % 3] = scale_to_byte(sample, header.maxval);
    }
}

// Where a P6 raster starts, given the position right after maxval's digits. Exactly one
// whitespace byte separates maxval from the raster. A comment may come before it (Netpbm:
// "before the whitespace character that delimits the raster", '#' through the next newline
// is a comment); as libnetpbm reads it, the newline that ends such a comment is that one
// whitespace byte, so "255#made by x\n" is followed by the raster.
std::size_t binary_raster_start(const Bytes& bytes, std::size_t after_maxval) {
    if (after_maxval == bytes.size()) throw ImageError("truncated PPM data: the file ends right after maxval");
    if (bytes[after_maxval] != '#') return after_maxval + 1;  // PpmNumberReader took only whitespace or '#'
    for (std::size_t at = after_maxval; at < bytes.size(); ++at)
        if (bytes[at] == '\n' || bytes[at] == '\r') return at + 1;
    throw ImageError("truncated PPM data: the comment after maxval runs to the end of the file, so there is no raster");
}

void read_ppm(const Bytes& bytes, bool ascii, Image& image) {
    PpmNumberReader numbers(bytes, 2);  // after the magic "P3" or "P6"
    const PpmHeader header = read_ppm_header(numbers);
    // Every sample takes at least one byte, so a raster larger than the rest of the file is
    // truncated; checking before allocating keeps a corrupt header from claiming gigabytes.
    if (header.sample_count() > bytes.size() - numbers.position()) throw ImageError("truncated PPM data");
    if (ascii) {
        read_ppm_ascii_raster(numbers, header, image);
        return;
    }
    read_ppm_binary_raster(bytes, binary_raster_start(bytes, numbers.position()), header, image);
}

ImageHeader header_of_size(long long width, long long height, bool sixteen_bit, std::uint64_t peak_bytes_per_pixel) {
    const std::uint64_t pixels = static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
    return {width, height, sixteen_bit, pixels * peak_bytes_per_pixel};
}

// Whether a PNG's texels may have alpha below 255, from its chunks before the pixel data: a
// colour type with alpha (4 grey + alpha, 6 RGBA) in IHDR, or a tRNS chunk (a transparent
// colour or palette alphas). Without either, every texel decodes opaque.
bool png_has_alpha_channel(const Bytes& bytes) {
    constexpr std::size_t kSignature = 8, kColourTypeAt = 25;
    if (bytes.size() <= kColourTypeAt) return false;
    if (bytes[kColourTypeAt] == 4 || bytes[kColourTypeAt] == 6) return true;
    for (std::size_t at = kSignature; at + 8 <= bytes.size();) {
        const std::uint64_t length = big_endian_32(bytes, at);
        const std::string type(bytes.begin() + at + 4, bytes.begin() + at + 8);
        if (type == "tRNS") return true;
        if (type == "IDAT" || type == "IEND") return false;
        at += 12 + length;  // length, type, data, CRC; 64-bit, so it cannot wrap
    }
    return false;
}

// libjpeg-turbo's peak, measured (docs/benchmarks.md, Figures behind design choices): the RGBA output, 4 bytes
// a pixel, and for a file of several scans (progressive) its whole coefficients, 2 bytes each,
// as many a pixel as the components' samples (1.5 for 4:2:0 colour, 3 for 4:4:4, 4 for CMYK).
// A single-scan file needs only a few rows of them; it is costed as the larger all the same.
std::optional<ImageHeader> read_jpeg_header(const Bytes& bytes) {
    const std::optional<JpegFrame> frame = find_jpeg_frame(bytes);
    if (!frame || frame->width == 0 || frame->height == 0) return std::nullopt;
    if (static_cast<long long>(frame->width) * frame->height > kMaxImagePixels) return std::nullopt;  // refused when decoded
    try {
        check_jpeg_frame_is_supported(*frame);
    } catch (const ImageError&) {
        return std::nullopt;  // refused, by name, when decoded
    }
    const std::uint64_t pixels = std::uint64_t(frame->width) * frame->height;
    ImageHeader header{frame->width, frame->height, false,
                       pixels * kRgba + static_cast<std::uint64_t>(2 * frame->samples_per_pixel * double(pixels))};
    header.format = "JPEG";
    return header;
}

std::optional<ImageHeader> read_png_header(const Bytes& bytes) {
    if (bytes.size() > static_cast<std::size_t>(INT_MAX)) return std::nullopt;
    const int length = static_cast<int>(bytes.size());
    int width = 0, height = 0, channels_in_file = 0;
    if (!stbi_info_from_memory(bytes.data(), length, &width, &height, &channels_in_file)) return std::nullopt;
    if (static_cast<long long>(width) * height > kMaxImagePixels) return std::nullopt;  // refused as too large when decoded
    const bool sixteen_bit = stbi_is_16_bit_from_memory(bytes.data(), length) != 0;
    // stb_image holds the inflated samples and its output at once (two RGBA buffers, of 16-bit
    // samples for a 16-bit PNG), then its output and our 8-bit copy: 8 or 16 bytes a pixel at
    // the peak, as measured (docs/benchmarks.md, Figures behind design choices).
    ImageHeader header = header_of_size(width, height, sixteen_bit, sixteen_bit ? 4 * kRgba : 2 * kRgba);
    header.format = "PNG";
    header.alpha_channel = png_has_alpha_channel(bytes);
    return header;
}

std::optional<ImageHeader> read_ppm_header_only(const Bytes& bytes) {
    try {
        PpmNumberReader numbers(bytes, 2);
        const PpmHeader header = read_ppm_header(numbers);
        // A raster larger than the file is refused as truncated when decoded.
        if (header.sample_count() > bytes.size() - numbers.position()) return std::nullopt;
        ImageHeader image_header = header_of_size(header.width, header.height, header.maxval > 255, kRgba);  // decoded in place
        image_header.format = "PPM";
        return image_header;
    } catch (const ImageError&) {
        return std::nullopt;
    }
}

}  // namespace

std::optional<ImageHeader> read_image_header(const std::vector<unsigned char>& bytes) {
    try {
        switch (detect_format(bytes)) {
            case FileFormat::Png: return read_png_header(bytes);
            case FileFormat::Jpeg: return read_jpeg_header(bytes);
            case FileFormat::PpmAscii:
            case FileFormat::PpmBinary: return read_ppm_header_only(bytes);
        }
    } catch (const ImageError&) {
    }
    return std::nullopt;
}

std::vector<unsigned char> read_image_file(const std::string& path) { return read_whole_file(path); }

std::shared_ptr<const Image> load_image(const std::string& path) {
    return load_image_from_bytes(read_whole_file(path), path);
}

std::shared_ptr<const Image> load_image_from_bytes(const std::vector<unsigned char>& bytes, const std::string& path) {
    // The checks read_whole_file makes on what it read, for bytes that came another way.
    if (bytes.empty()) throw ImageError("empty file");
    if (bytes.size() > static_cast<std::size_t>(INT_MAX)) throw ImageError("file too large");
    auto image = std::make_shared<Image>();
    image->path = path;
    switch (detect_format(bytes)) {
        case FileFormat::Png:
            check_png_size(bytes);
            decode_with_stb(bytes, "PNG", *image);
            break;
        case FileFormat::Jpeg:
            decode_jpeg_file(bytes, *image);
            break;
        case FileFormat::PpmAscii: read_ppm(bytes, true, *image); break;
        case FileFormat::PpmBinary: read_ppm(bytes, false, *image); break;
    }
    return image;
}

std::shared_ptr<const Image> make_placeholder_image(const std::string& path_it_replaces) {
    constexpr int kSize = 8;
    constexpr std::uint8_t kMagenta[kRgba] = {255, 0, 255, 255};
    constexpr std::uint8_t kGrey[kRgba] = {128, 128, 128, 255};
    auto image = std::make_shared<Image>();
    image->path = path_it_replaces;
    image->width = kSize;
    image->height = kSize;
    for (int row = 0; row < kSize; ++row) {
        for (int col = 0; col < kSize; ++col) {
            const std::uint8_t* texel = (row + col) % 2 == 0 ? kMagenta : kGrey;
            image->rgba.insert(image->rgba.end(), texel, texel + kRgba);
        }
    }
    return image;
}

}  // namespace clr
