// --display-server HOST:PORT (docs/command-line.md, Streaming to tev): a running tev viewer
// shows each frame as it is rendered, as pbrt's --display-server does. The viewer is a
// convenience: one that is not running, cannot be reached or goes away is a warning, and the
// render goes on and writes its files as without it.
#pragma once

#include <chrono>
#include <iosfwd>
#include <memory>
#include <string>

#include "core/image.h"

namespace clr {

class TevConnection;

struct DisplayAddress {
    std::string host;  // a name or an address; an IPv6 address without its brackets
    std::string port;  // 1 to 65535, decimal
};

// "HOST:PORT", "[IPv6]:PORT". Throws UsageError naming the text for anything else.
DisplayAddress parse_display_address(const std::string& text);

// The frames of one render, shown in tev as one image named `name`, replaced frame by frame.
class DisplayStream {
public:
    // Does nothing when `address` is empty. Otherwise connects (within `timeout`) and creates
    // the image, of width x height and channels R, G, B; on failure writes one warning to
    // `warnings` and shows nothing.
    DisplayStream(const std::string& address, std::string name, int width, int height,
                  std::chrono::milliseconds timeout = std::chrono::seconds(3), std::ostream* warnings = nullptr);
    ~DisplayStream();
    DisplayStream(const DisplayStream&) = delete;
    DisplayStream& operator=(const DisplayStream&) = delete;

    // Sends the frame's pixels, bands of rows at a time, as linear values: each byte decoded
    // by the sRGB transfer function (core/srgb_transfer.h), so that tev shows the picture of
    // the PNG. After a failure: one warning, and no frame is sent any more.
    void show(const Image& frame);
    bool connected() const { return connection_ != nullptr; }

private:
    void give_up(const std::string& why);

    std::string address_;
    std::string name_;
    int width_ = 0, height_ = 0;
    std::ostream* warnings_;
    std::unique_ptr<TevConnection> connection_;
};

}  // namespace clr
