#include "app/display_server.h"

#include <algorithm>
#include <iostream>
#include <regex>
#include <vector>

#include "core/errors.h"
#include "core/interruption.h"
#include "core/printable_text.h"
#include "core/srgb_transfer.h"
#include "output/tev_connection.h"
#include "output/tev_packets.h"

namespace clr {
namespace {

const std::vector<std::string> kChannels = {"R", "G", "B"};

// Floats of one UpdateImage packet at most: 4 MiB, small enough for tev's receive buffer to
// take without growing much, large enough that a frame is a few packets.
constexpr std::size_t kFloatsPerPacket = std::size_t(1) << 20;

}  // namespace

DisplayAddress parse_display_address(const std::string& text) {
    // A host of letters, digits, '.', '-' and '_' (a name or IPv4 address), or an IPv6
    // address in brackets; a port of 1 to 5 digits.
    static const std::regex pattern(R"((?:([A-Za-z0-9._-]+)|\[([0-9A-Fa-f:.]+)\]):([0-9]{1,5}))");
    std::smatch match;
    if (std::regex_match(text, match, pattern)) {
        const int port = std::stoi(match[3]);
        if (port >= 1 && port <= 65535)
            return {match[1].matched ? match[1].str() : match[2].str(), std::to_string(port)};
    }
    throw UsageError("--display-server " + printable(text) +
                     ": expected HOST:PORT, e.g. localhost:14158 or [::1]:14158, with a port of 1 to 65535");
}

DisplayStream::DisplayStream(const std::string& address, std::string name, int width, int height,
                             std::chrono::milliseconds timeout, std::ostream* warnings)
    : address_(address), name_(std::move(name)), width_(width), height_(height),
      warnings_(warnings ? warnings : &std::cerr) {
    if (address.empty()) return;
    const DisplayAddress where = parse_display_address(address);
    try {
        connection_ = std::make_unique<TevConnection>(where.host, where.port, timeout);
        connection_->send(tev_create_image(name_, width_, height_, kChannels));
    } catch (const TevConnectionError& error) {
        give_up(error.what());
    }
}

DisplayStream::~DisplayStream() = default;

void DisplayStream::show(const Image& frame) {
    if (!connection_) return;
    const int rows_per_packet =
        static_cast<int>(std::max<std::size_t>(1, kFloatsPerPacket / (static_cast<std::size_t>(frame.width) * 3)));
    std::vector<float> values;
    try {
        for (int first = 0; first < frame.height; first += rows_per_packet) {
            const int rows = std::min(rows_per_packet, frame.height - first);
            values.resize(static_cast<std::size_t>(frame.width) * rows * 3);
            std::size_t i = 0;
            for (int row = first; row < first + rows; ++row)
                for (int col = 0; col < frame.width; ++col)
                    for (int c = 0; c < 3; ++c) values[i++] = srgb_byte_to_linear(frame.at(col, row, c));
            connection_->send(tev_update_image(name_, kChannels, 0, first, frame.width, rows, values));
        }
    } catch (const TevConnectionError& error) {
        give_up(error.what());
    }
}

void DisplayStream::give_up(const std::string& why) {
    connection_.reset();
    if (interruption_requested()) return;  // the run stops at once and says why
    *warnings_ << "clrender: warning: --display-server " << printable(address_) << ": " << printable(why)
               << "; the render goes on without the viewer\n";
}

}  // namespace clr
