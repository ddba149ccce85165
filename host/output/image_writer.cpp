// Frame output: PNG through zlib, PPM P6 by hand (a header and the bytes). Both go
// through AtomicFile, and both are deterministic: the same image always gives the same bytes.
#include "output/image_writer.h"

#include <zlib.h>

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

// PNG written with zlib directly: RGB, 8 bits, every row with the "Up" filter, deflated at
// level 1 with run-length matching. stb_image_write (all five filters tried per row, its own
// deflate) took 35 ms for a 600x600 frame, 18 ms at best with one filter; this takes about
// 4.5 ms, and the files of rendered frames came out smaller than stb's level 8.
void put_u32(std::vector<std::uint8_t>& out, std::uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(value >> shift));
}

void write_chunk(AtomicFile& file, const char type[4], const std::uint8_t* data, std::size_t size) {
    std::vector<std::uint8_t> header;
    put_u32(header, static_cast<std::uint32_t>(size));
    header.insert(header.end(), type, type + 4);
    uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(type), 4);
    if (size > 0) crc = crc32_z(crc, data, size);
    std::vector<std::uint8_t> trailer;
    put_u32(trailer, static_cast<std::uint32_t>(crc));
    file.write(header.data(), header.size());
    if (size > 0) file.write(data, size);
    file.write(trailer.data(), trailer.size());
}

void write_png(AtomicFile& file, const Image& image) {
    const std::size_t width = static_cast<std::size_t>(image.width), row_bytes = width * 3;
    // Filtered rows: a filter-type byte (2, "Up"), then each byte minus the one above it.
    std::vector<std::uint8_t> filtered((row_bytes + 1) * image.height);
    for (int row = 0; row < image.height; ++row) {
        std::uint8_t* out = filtered.data() + row * (row_bytes + 1);
        *out++ = 2;
        const std::uint8_t* pixel = image.rgba.data() + row * width * 4;
        const std::uint8_t* above = row > 0 ? pixel - width * 4 : nullptr;
        for (std::size_t col = 0; col < width; ++col, pixel += 4, out += 3)
            for (int c = 0; c < 3; ++c) out[c] = static_cast<std::uint8_t>(pixel[c] - (above ? above[col * 4 + c] : 0));
    }
    static const std::uint8_t signature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
    file.write(signature, sizeof signature);
    std::vector<std::uint8_t> header;
    put_u32(header, static_cast<std::uint32_t>(image.width));
    put_u32(header, static_cast<std::uint32_t>(image.height));
    header.insert(header.end(), {8, 2, 0, 0, 0});  // 8 bits, RGB, deflate, adaptive filters, no interlace
    write_chunk(file, "IHDR", header.data(), header.size());

    // One zlib stream, fed and emitted in pieces (zlib counts in 32 bits), an IDAT chunk for
    // every 1 MiB of it.
    z_stream stream{};
    if (deflateInit2(&stream, 1, Z_DEFLATED, 15, 8, Z_RLE) != Z_OK)
        throw OutputError(file.final_path() + ": the PNG encoder failed (zlib)");
    std::vector<std::uint8_t> piece(std::size_t{1} << 20);
    std::size_t fed = 0;
    int status = Z_OK;
    try {
        while (status == Z_OK) {
            if (stream.avail_in == 0 && fed < filtered.size()) {
                std::size_t size = std::min<std::size_t>(filtered.size() - fed, std::size_t{1} << 30);
                stream.next_in = filtered.data() + fed;
                stream.avail_in = static_cast<uInt>(size);
                fed += size;
            }
            stream.next_out = piece.data();
            stream.avail_out = static_cast<uInt>(piece.size());
            status = deflate(&stream, fed == filtered.size() ? Z_FINISH : Z_NO_FLUSH);
            std::size_t produced = piece.size() - stream.avail_out;
            if (produced > 0) write_chunk(file, "IDAT", piece.data(), produced);
        }
    } catch (...) {
        deflateEnd(&stream);
        throw;
    }
    deflateEnd(&stream);
    if (status != Z_STREAM_END) throw OutputError(file.final_path() + ": the PNG encoder failed (zlib)");
    write_chunk(file, "IEND", nullptr, 0);
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
