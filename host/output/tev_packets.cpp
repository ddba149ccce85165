#include "output/tev_packets.h"

#include <cstring>
#include <limits>
#include <stdexcept>

namespace clr {
namespace {

// Writes each field in tev's byte order (little-endian) whatever the host's.
class PacketWriter {
public:
    explicit PacketWriter(TevPacketType type) {
        integer(std::uint32_t{0}, 4);  // the length, set by finish()
        bytes_.push_back(static_cast<std::uint8_t>(type));
    }
    void boolean(bool value) { bytes_.push_back(value ? 1 : 0); }
    void int32(std::int32_t value) { integer(static_cast<std::uint32_t>(value), 4); }
    void int64(std::int64_t value) { integer(static_cast<std::uint64_t>(value), 8); }
    void text(const std::string& value) {
        // A 0 byte inside would end the string early and shift every later field.
        if (value.find('\0') != std::string::npos) throw std::invalid_argument("tev packet: a name holds a 0 byte");
        bytes_.insert(bytes_.end(), value.begin(), value.end());
        bytes_.push_back(0);
    }
    void floats(const std::vector<float>& values) {
        for (float value : values) {
            std::uint32_t bits = 0;
            std::memcpy(&bits, &value, sizeof bits);
            integer(bits, 4);
        }
    }
    void reserve(std::size_t bytes) { bytes_.reserve(bytes); }
    TevPacket finish() {
        if (bytes_.size() > std::numeric_limits<std::uint32_t>::max())
            throw std::invalid_argument("tev packet: larger than 4 GiB");
        const auto length = static_cast<std::uint32_t>(bytes_.size());
        for (int i = 0; i < 4; ++i) bytes_[i] = static_cast<std::uint8_t>(length >> (8 * i));
        return std::move(bytes_);
    }

private:
    void integer(std::uint64_t value, int size) {
        for (int i = 0; i < size; ++i) bytes_.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
    }
    TevPacket bytes_;
};

}  // namespace

TevPacket tev_create_image(const std::string& name, int width, int height, const std::vector<std::string>& channels,
                           bool grab_focus) {
    PacketWriter packet(TevPacketType::CreateImage);
    packet.boolean(grab_focus);
    packet.text(name);
    packet.int32(width);
    packet.int32(height);
    packet.int32(static_cast<std::int32_t>(channels.size()));
    for (const std::string& channel : channels) packet.text(channel);
    return packet.finish();
}

TevPacket tev_update_image(const std::string& name, const std::vector<std::string>& channels, int x, int y, int width,
                           int height, const std::vector<float>& values, bool grab_focus) {
    const std::size_t count = channels.size();
    if (count == 0 || width <= 0 || height <= 0 ||
        values.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * count)
        throw std::invalid_argument("tev packet: the values do not fill the rectangle's channels");
    PacketWriter packet(TevPacketType::UpdateImage);
    packet.reserve(64 + name.size() + values.size() * sizeof(float));
    packet.boolean(grab_focus);
    packet.text(name);
    packet.int32(static_cast<std::int32_t>(count));
    for (const std::string& channel : channels) packet.text(channel);
    packet.int32(x);
    packet.int32(y);
    packet.int32(width);
    packet.int32(height);
    for (std::size_t c = 0; c < count; ++c) packet.int64(static_cast<std::int64_t>(c));      // offsets
    for (std::size_t c = 0; c < count; ++c) packet.int64(static_cast<std::int64_t>(count));  // strides
    packet.floats(values);
    return packet.finish();
}

TevPacket tev_close_image(const std::string& name) {
    PacketWriter packet(TevPacketType::CloseImage);
    packet.text(name);
    return packet.finish();
}

}  // namespace clr
