// Float channels rather than half: half keeps 11 bits, and would move values near a rounding
// step of the PNG's bytes to the other byte (exr_values.h keeps them a hundredth of a step
// away, far less than half's resolution), at twice half's size; ZIP compression keeps it
// lossless.
#include "output/exr_writer.h"

#include <Iex.h>
#include <ImfChannelList.h>
#include <ImfChromaticities.h>
#include <ImfStandardAttributes.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfOutputFile.h>

#include <algorithm>
#include <cstdint>

#include "core/errors.h"
#include "output/exr_values.h"

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
    // sRGB's primaries and white point (Rec. 709's, OpenEXR's default), said explicitly so that
    // a viewer need not assume them: the values are linear light in the PNG's colour space.
    Imf::addChromaticities(header, Imf::Chromaticities());
    std::vector<float> values = exr_values(image);
    Imf::FrameBuffer frame;
    const std::size_t pixel_stride = 4 * sizeof(float);
    const std::size_t row_stride = pixel_stride * static_cast<std::size_t>(image.width);
    char* base = reinterpret_cast<char*>(values.data());
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
    const std::size_t values = static_cast<std::size_t>(image.width) * image.height * 4;
    if (image.linear.size() != values || image.rgba.size() != values)
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
