// Float channels rather than half: the file then holds exactly the values the display bytes
// are rounded from (half keeps 11 bits, and would move pixels near a rounding step to the
// other byte), at twice half's size; ZIP compression keeps it lossless.
#include "output/exr_writer.h"

#include <Iex.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfOutputFile.h>

#include <algorithm>
#include <cstdint>

#include "core/errors.h"

namespace clr {
namespace {

// An OpenEXR output stream into memory (the encoder seeks back to write its offset table).
class MemoryStream : public Imf::OStream {
public:
    MemoryStream() : Imf::OStream("memory") {}
    void write(const char c[], int n) override {
        if (position_ + n > bytes_.size()) bytes_.resize(position_ + n);
        std::copy(c, c + n, bytes_.begin() + static_cast<std::ptrdiff_t>(position_));
        position_ += n;
    }
    std::uint64_t tellp() override { return position_; }
    void seekp(std::uint64_t position) override { position_ = position; }
    std::vector<char>& bytes() { return bytes_; }

private:
    std::vector<char> bytes_;
    std::uint64_t position_ = 0;
};

void write_channels(Imf::OStream& stream, const Image& image) {
    const bool alpha = image.write_alpha;
    const char* names[] = {"R", "G", "B", "A"};
    const int channels = alpha ? 4 : 3;
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::FrameBuffer frame;
    const std::size_t pixel_stride = 4 * sizeof(float);
    const std::size_t row_stride = pixel_stride * static_cast<std::size_t>(image.width);
    char* base = reinterpret_cast<char*>(const_cast<float*>(image.linear.data()));
    for (int c = 0; c < channels; ++c) {
        header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
        frame.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), pixel_stride, row_stride));
    }
    Imf::OutputFile file(stream, header);
    file.setFrameBuffer(frame);
    file.writePixels(image.height);
}

}  // namespace

std::vector<char> encode_exr(const std::string& path, const Image& image) {
    if (image.linear.size() != static_cast<std::size_t>(image.width) * image.height * 4)
        throw OutputError(path + ": the frame has no linear colours to write as EXR");
    MemoryStream stream;
    try {
        write_channels(stream, image);
    } catch (const Iex::BaseExc& error) {  // std::bad_alloc goes on: out of memory has its own exit code
        throw OutputError(path + ": the EXR encoder failed (" + error.what() + ")");
    }
    return std::move(stream.bytes());
}

}  // namespace clr
