#include "scene/jpeg_checks.h"

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>

#include "scene/image_loader.h"  // ImageError

namespace clr {

std::optional<JpegFrame> find_jpeg_frame(const std::vector<unsigned char>& bytes) {
    const std::size_t size = bytes.size();
    std::size_t at = 2;  // after the start-of-image marker
    while (at + 1 < size && bytes[at] == 0xFF) {
        while (at < size && bytes[at] == 0xFF) ++at;  // fill bytes
        if (at + 2 >= size) return std::nullopt;
        const unsigned marker = bytes[at++];
        const std::size_t length = std::size_t(bytes[at]) << 8 | bytes[at + 1];
        if (length < 2 || at + length > size) return std::nullopt;
        // SOF0-SOF15 but for DHT (C4), JPG (C8) and DAC (CC), which share the range.
        const bool frame = marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
        if (frame) {
            if (length < 8) return std::nullopt;
            const std::size_t body = at + 2;
            JpegFrame found{marker, bytes[body], unsigned(bytes[body + 1]) << 8 | bytes[body + 2],
                            unsigned(bytes[body + 3]) << 8 | bytes[body + 4], bytes[body + 5]};
            // Each component: id, sampling factors (horizontal << 4 | vertical), table.
            if (found.components == 0 || length < 8 + 3 * std::size_t(found.components)) return std::nullopt;
            unsigned largest_h = 1, largest_v = 1, samples = 0;
            for (unsigned c = 0; c < found.components; ++c) {
                const unsigned factors = bytes[body + 7 + 3 * c], h = factors >> 4, v = factors & 15;
                largest_h = std::max(largest_h, h);
                largest_v = std::max(largest_v, v);
                samples += h * v;
            }
            found.samples_per_pixel = double(samples) / (largest_h * largest_v);
            return found;
        }
        if (marker == 0xDA || marker == 0xD9) return std::nullopt;  // a scan or the end before any frame
        at += length;
    }
    return std::nullopt;
}

void check_jpeg_frame_is_supported(const JpegFrame& frame) {
    // SOFn's low four bits: 8 arithmetic coding, 4 hierarchical (differential), 3 lossless,
    // 2 progressive. libjpeg-turbo 2.1 decodes neither lossless nor hierarchical JPEG.
    const unsigned process = frame.marker & 15;
    if ((process & 3) == 3 || (process & 4)) {
        std::string kind;
        if (process & 8) kind += "arithmetic-coded ";
        if (process & 4) kind += "hierarchical ";
        kind += (process & 3) == 3 ? "lossless " : (process & 3) == 2 ? "progressive " : "";
        throw ImageError("unsupported JPEG: " + kind + "JPEG (SOF" + std::to_string(process) +
                         ") is not supported; clrender reads baseline and progressive JPEG (save the image as "
                         "PNG, or as a baseline JPEG)");
    }
    if (frame.precision != 8)
        throw ImageError("unsupported JPEG: " + std::to_string(frame.precision) +
                         "-bit samples are not supported; clrender reads 8-bit JPEG (save the image as PNG)");
    // Two components are grey with another channel (often alpha), which no colour space names:
    // libjpeg cannot turn them into colour, and a JPEG's second channel is no alpha clrender knows.
    if (frame.components != 1 && frame.components != 3 && frame.components != 4)
        throw ImageError("unsupported JPEG: " + std::to_string(frame.components) +
                         " colour components are not supported; clrender reads JPEG of 1 (grey), 3 (colour) or 4 "
                         "(CMYK) components (save the image as PNG, with alpha if the extra channel is one)");
}

}  // namespace clr
