#include "output/png_pixel_data.h"

#include <isa-l/igzip_lib.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace clr {
namespace {

// Rows filtered and handed to the compressor at a time: a small buffer instead of a filtered
// copy of the whole image. Where the compressor's input is cut changes its output, so this is
// a constant: the same image gives the same bytes.
constexpr int kStripRows = 32;

// The compressed stream grows by this much at a time.
constexpr std::size_t kOutputSlice = std::size_t{1} << 16;

constexpr std::uint8_t kFilterUp = 2;  // PNG filter type "Up"

// Row `row` as a PNG scanline: the filter type, then each of its bytes minus the byte above it
// (modulo 256; the row above the first is zeros). `channels` of each RGBA pixel are kept.
void filter_row_up(const Image& image, int row, int channels, std::uint8_t* scanline) {
    scanline[0] = kFilterUp;
    std::uint8_t* out = scanline + 1;
    const std::size_t row_bytes = static_cast<std::size_t>(image.width) * 4;
    const std::uint8_t* pixel = image.rgba.data() + row * row_bytes;
    if (row == 0) {
        for (int x = 0; x < image.width; ++x, pixel += 4, out += channels)
            for (int c = 0; c < channels; ++c) out[c] = pixel[c];
        return;
    }
    const std::uint8_t* above = pixel - row_bytes;
    for (int x = 0; x < image.width; ++x, pixel += 4, above += 4, out += channels)
        for (int c = 0; c < channels; ++c) out[c] = static_cast<std::uint8_t>(pixel[c] - above[c]);
}

// igzip at level 1: its fastest level with Huffman codes fitted to the data. On rendered
// frames it deflates 4-6 times as fast as zlib at level 1 with run-length matching, and its
// output is as small or smaller.
class IgzipStream {
public:
    IgzipStream() : level_buffer_(ISAL_DEF_LVL1_DEFAULT) {
        isal_deflate_init(&stream_);
        stream_.level = 1;
        stream_.level_buf = level_buffer_.data();
        stream_.level_buf_size = static_cast<std::uint32_t>(level_buffer_.size());
        stream_.gzip_flag = IGZIP_ZLIB;  // the zlib header and Adler-32 trailer PNG requires
        stream_.flush = NO_FLUSH;
    }

    // Compresses `size` bytes (the last ones when `last`) onto the end of `out`.
    void add(const std::uint8_t* data, std::size_t size, bool last, std::vector<std::uint8_t>& out) {
        stream_.next_in = const_cast<std::uint8_t*>(data);
        stream_.avail_in = static_cast<std::uint32_t>(size);
        stream_.end_of_stream = last ? 1 : 0;
        do {
            const std::size_t used = out.size();
            out.resize(used + kOutputSlice);
            stream_.next_out = out.data() + used;
            stream_.avail_out = static_cast<std::uint32_t>(kOutputSlice);
            const int result = isal_deflate(&stream_);
            out.resize(out.size() - stream_.avail_out);
            if (result != COMP_OK) throw std::runtime_error("igzip failed with code " + std::to_string(result));
        } while (stream_.avail_in > 0 || (last && stream_.internal_state.state != ZSTATE_END));
    }

private:
    std::vector<std::uint8_t> level_buffer_;  // igzip's hash tables for level 1
    isal_zstream stream_{};
};

}  // namespace

std::vector<std::uint8_t> png_pixel_data(const Image& image) {
    const int channels = image.write_alpha ? 4 : 3;
    const std::size_t scanline_bytes = 1 + static_cast<std::size_t>(image.width) * channels;
    if (scanline_bytes * kStripRows > UINT32_MAX)  // igzip counts its input in 32 bits
        throw std::length_error("rows of " + std::to_string(image.width) + " pixels are too long to compress");
    std::vector<std::uint8_t> strip(scanline_bytes * kStripRows);
    std::vector<std::uint8_t> out;
    out.reserve(scanline_bytes * image.height / 4);  // rendered frames deflate to a tenth or so
    IgzipStream stream;
    for (int first = 0; first < image.height; first += kStripRows) {
        const int rows = std::min(kStripRows, image.height - first);
        for (int i = 0; i < rows; ++i) filter_row_up(image, first + i, channels, strip.data() + i * scanline_bytes);
        stream.add(strip.data(), rows * scanline_bytes, first + rows == image.height, out);
    }
    return out;
}

}  // namespace clr
