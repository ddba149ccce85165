#include "output/fake_tev_server.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <stdexcept>

namespace clr::testing {
namespace {

// Reads the packet's fields in order; throws std::runtime_error past its end.
class FieldReader {
public:
    explicit FieldReader(const std::vector<std::uint8_t>& bytes) : bytes_(bytes) {}
    std::uint64_t unsigned_le(int size) {
        need(size);
        std::uint64_t value = 0;
        for (int i = 0; i < size; ++i) value |= static_cast<std::uint64_t>(bytes_[at_ + i]) << (8 * i);
        at_ += size;
        return value;
    }
    std::int32_t int32() { return static_cast<std::int32_t>(static_cast<std::uint32_t>(unsigned_le(4))); }
    std::int64_t int64() { return static_cast<std::int64_t>(unsigned_le(8)); }
    bool boolean() { return unsigned_le(1) != 0; }
    std::string text() {
        std::string value;
        for (;;) {
            need(1);
            const char c = static_cast<char>(bytes_[at_++]);
            if (c == '\0') return value;
            value += c;
        }
    }
    float float32_at(std::size_t index) {  // the index-th float of the data after the fields
        const std::size_t start = at_ + index * 4;
        if (start + 4 > bytes_.size()) throw std::runtime_error("float past the packet's end");
        std::uint32_t bits = 0;
        for (int i = 0; i < 4; ++i) bits |= static_cast<std::uint32_t>(bytes_[start + i]) << (8 * i);
        float value = 0;
        std::memcpy(&value, &bits, 4);
        return value;
    }
    std::size_t left() const { return bytes_.size() - at_; }

private:
    void need(std::size_t size) const {
        if (at_ + size > bytes_.size()) throw std::runtime_error("field past the packet's end");
    }
    const std::vector<std::uint8_t>& bytes_;
    std::size_t at_ = 0;
};

bool read_exactly(int socket, std::uint8_t* data, std::size_t size) {
    std::size_t done = 0;
    while (done < size) {
        const ssize_t got = ::recv(socket, data + done, size - done, 0);
        if (got <= 0) return false;
        done += static_cast<std::size_t>(got);
    }
    return true;
}

}  // namespace

FakeTevServer::FakeTevServer(Behaviour behaviour, int packets) : behaviour_(behaviour), packets_allowed_(packets) {
    listener_ = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    address.sin_port = 0;  // a free port
    if (listener_ < 0 || ::bind(listener_, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
        ::listen(listener_, 1) != 0)
        throw std::runtime_error("fake tev: cannot listen");
    socklen_t length = sizeof address;
    ::getsockname(listener_, reinterpret_cast<sockaddr*>(&address), &length);
    port_ = ntohs(address.sin_port);
    thread_ = std::thread([this] { serve(); });
}

FakeTevServer::~FakeTevServer() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
    if (listener_ >= 0) ::close(listener_);
}

FakeTevServer::Received FakeTevServer::wait() {
    if (thread_.joinable()) thread_.join();
    return received_;
}

void FakeTevServer::serve() {
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    pollfd waiting{listener_, POLLIN, 0};
    while (!stop_ && std::chrono::steady_clock::now() < end) {
        if (::poll(&waiting, 1, 50) <= 0) continue;
        const int client = ::accept(listener_, nullptr, nullptr);
        if (client < 0) continue;
        if (behaviour_ == Behaviour::NeverRead) {
            while (!stop_ && std::chrono::steady_clock::now() < end) std::this_thread::sleep_for(std::chrono::milliseconds(20));
        } else {
            read_packets(client);
        }
        ::close(client);
        return;
    }
}

void FakeTevServer::read_packets(int client) {
    for (int count = 0;; ++count) {
        if (behaviour_ == Behaviour::CloseEarly && count == packets_allowed_) return;
        std::uint8_t length_bytes[4];
        if (!read_exactly(client, length_bytes, 4)) return;  // the client closed
        const std::uint32_t length = length_bytes[0] | length_bytes[1] << 8 | length_bytes[2] << 16 |
                                     static_cast<std::uint32_t>(length_bytes[3]) << 24;
        if (length < 5 || length > (1u << 30)) {
            received_.problem = "packet length " + std::to_string(length);
            return;
        }
        std::vector<std::uint8_t> packet(length - 4);  // the length counts its own 4 bytes
        if (!read_exactly(client, packet.data(), packet.size())) {
            received_.problem = "packet cut short";
            return;
        }
        try {
            apply(packet);
        } catch (const std::exception& error) {
            received_.problem = error.what();
            return;
        }
    }
}

void FakeTevServer::apply(const std::vector<std::uint8_t>& packet) {
    FieldReader fields(packet);
    const int type = static_cast<int>(fields.unsigned_le(1));
    received_.packet_types.push_back(type);
    if (type == 4) {  // CreateImage
        fields.boolean();
        const std::string name = fields.text();
        TevImage image;
        image.width = fields.int32();
        image.height = fields.int32();
        const int count = fields.int32();
        for (int c = 0; c < count; ++c) image.channels.push_back(fields.text());
        for (const std::string& channel : image.channels)
            image.values[channel].assign(static_cast<std::size_t>(image.width) * image.height, 0.0f);
        if (fields.left() != 0) throw std::runtime_error("CreateImage: bytes after the fields");
        received_.images[name] = image;
    } else if (type == 6) {  // UpdateImage, version 3
        fields.boolean();
        const std::string name = fields.text();
        const int count = fields.int32();
        std::vector<std::string> channels;
        for (int c = 0; c < count; ++c) channels.push_back(fields.text());
        const int x = fields.int32(), y = fields.int32(), width = fields.int32(), height = fields.int32();
        std::vector<std::int64_t> offsets, strides;
        for (int c = 0; c < count; ++c) offsets.push_back(fields.int64());
        for (int c = 0; c < count; ++c) strides.push_back(fields.int64());
        auto found = received_.images.find(name);
        if (found == received_.images.end()) throw std::runtime_error("UpdateImage of an image never created");
        TevImage& image = found->second;
        if (x < 0 || y < 0 || width <= 0 || height <= 0 || x + width > image.width || y + height > image.height)
            throw std::runtime_error("UpdateImage outside the image");
        std::size_t floats_needed = 0;
        const std::size_t pixels = static_cast<std::size_t>(width) * height;
        for (int c = 0; c < count; ++c)
            floats_needed = std::max<std::size_t>(floats_needed, offsets[c] + (pixels - 1) * strides[c] + 1);
        if (fields.left() != floats_needed * 4) throw std::runtime_error("UpdateImage: data size does not match");
        for (int c = 0; c < count; ++c) {
            auto channel = image.values.find(channels[c]);
            if (channel == image.values.end()) throw std::runtime_error("UpdateImage of an unknown channel");
            for (std::size_t p = 0; p < pixels; ++p) {
                const std::size_t row = y + p / width, col = x + p % width;
                channel->second[row * image.width + col] = fields.float32_at(offsets[c] + p * strides[c]);
            }
        }
        ++image.updates;
    } else if (type == 2) {  // CloseImage
        received_.images.erase(fields.text());
    } else {
        throw std::runtime_error("unexpected packet type " + std::to_string(type));
    }
}

}  // namespace clr::testing
