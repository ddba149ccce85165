// --display-server's stream (host/app/display_server.h) against a stand-in tev that parses the
// packets on its own (fake_tev_server.h): the image it rebuilds is the frame's bytes decoded
// by the sRGB transfer function; a viewer that is not there, closes the connection or stops
// reading is one warning and never an exception; HOST:PORT is checked.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <sstream>
#include <thread>

#include "app/display_server.h"
#include "core/errors.h"
#include "output/fake_tev_server.h"

namespace clr {
namespace {

using testing::FakeTevServer;
using namespace std::chrono_literals;

// A frame whose pixels each have other bytes; tall enough for several UpdateImage packets
// (2^20 floats each: 1000 pixels a row makes 349 rows a packet).
Image test_frame(int width, int height) {
    Image frame;
    frame.width = width;
    frame.height = height;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            frame.rgba.insert(frame.rgba.end(), {static_cast<std::uint8_t>(x * 7 + y), static_cast<std::uint8_t>(y * 3),
                                                 static_cast<std::uint8_t>(255 - x % 256), 255});
    return frame;
}

// IEC 61966-2-1, written out here rather than taken from clrender.
double srgb_decoded(int byte) {
    const double v = byte / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

// A port on 127.0.0.1 where nothing listens: one that was free a moment ago.
int closed_port() {
    const int socket = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ::bind(socket, reinterpret_cast<sockaddr*>(&address), sizeof address);
    socklen_t length = sizeof address;
    ::getsockname(socket, reinterpret_cast<sockaddr*>(&address), &length);
    ::close(socket);
    return ntohs(address.sin_port);
}

int count_of(const std::string& text, const std::string& word) {
    int count = 0;
    for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++count;
    return count;
}

TEST(TevDisplay, TevRebuildsTheFrameAsLinearValues) {
    FakeTevServer tev;
    const Image frame = test_frame(1000, 700);
    std::ostringstream warnings;
    {
        DisplayStream stream(tev.address(), "scene", frame.width, frame.height, 3s, &warnings);
        ASSERT_TRUE(stream.connected()) << warnings.str();
        stream.show(frame);
        stream.show(frame);  // the next frame of an animation replaces it
    }
    const FakeTevServer::Received received = tev.wait();
    EXPECT_EQ(received.problem, "");
    EXPECT_EQ(warnings.str(), "");
    ASSERT_EQ(received.images.count("scene"), 1u);
    const FakeTevServer::TevImage& image = received.images.at("scene");
    EXPECT_EQ(image.width, 1000);
    EXPECT_EQ(image.height, 700);
    EXPECT_EQ(image.channels, (std::vector<std::string>{"R", "G", "B"}));
    EXPECT_EQ(image.updates, 2 * 3);  // 700 rows in packets of 349 rows, twice
    EXPECT_EQ(received.packet_types.front(), 4);  // CreateImage first
    const char* names[] = {"R", "G", "B"};
    int wrong = 0;
    for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x)
            for (int c = 0; c < 3; ++c)
                if (std::abs(image.values.at(names[c])[y * frame.width + x] - srgb_decoded(frame.at(x, y, c))) > 1e-6)
                    ++wrong;
    EXPECT_EQ(wrong, 0);
}

TEST(TevDisplay, NoTevRunningIsOneWarning) {
    std::ostringstream warnings;
    const std::string address = "127.0.0.1:" + std::to_string(closed_port());
    DisplayStream stream(address, "scene", 4, 4, 3s, &warnings);
    EXPECT_FALSE(stream.connected());
    stream.show(test_frame(4, 4));  // nothing, and no second warning
    EXPECT_EQ(count_of(warnings.str(), "clrender: warning: --display-server " + address + ": cannot connect"), 1)
        << warnings.str();
    EXPECT_NE(warnings.str().find("the render goes on without the viewer"), std::string::npos);
}

TEST(TevDisplay, TevClosingTheConnectionIsOneWarning) {
    FakeTevServer tev(FakeTevServer::Behaviour::CloseEarly, 1);  // reads the CreateImage only
    std::ostringstream warnings;
    DisplayStream stream(tev.address(), "scene", 200, 200, 3s, &warnings);
    ASSERT_TRUE(stream.connected()) << warnings.str();
    tev.wait();  // closed
    const Image frame = test_frame(200, 200);
    for (int i = 0; i < 20 && stream.connected(); ++i) {
        stream.show(frame);
        std::this_thread::sleep_for(10ms);
    }
    EXPECT_FALSE(stream.connected());
    stream.show(frame);
    EXPECT_EQ(count_of(warnings.str(), "clrender: warning:"), 1) << warnings.str();
    EXPECT_NE(warnings.str().find("the connection ended"), std::string::npos) << warnings.str();
}

// A viewer that accepts and then reads nothing: the send gives up after the timeout instead
// of blocking the render for ever.
TEST(TevDisplay, ATevThatStopsReadingIsAWarningAfterTheTimeout) {
    FakeTevServer tev(FakeTevServer::Behaviour::NeverRead);
    std::ostringstream warnings;
    DisplayStream stream(tev.address(), "scene", 2000, 2000, 300ms, &warnings);
    ASSERT_TRUE(stream.connected()) << warnings.str();
    stream.show(test_frame(2000, 2000));  // 48 MB of floats: more than the socket buffers hold
    EXPECT_FALSE(stream.connected());
    EXPECT_NE(warnings.str().find("took no data for 300 ms"), std::string::npos) << warnings.str();
}

TEST(TevDisplay, NoAddressNoStream) {
    std::ostringstream warnings;
    DisplayStream stream("", "scene", 4, 4, 3s, &warnings);
    EXPECT_FALSE(stream.connected());
    stream.show(test_frame(4, 4));
    EXPECT_EQ(warnings.str(), "");
}

TEST(TevDisplay, DisplayAddresses) {
    const DisplayAddress local = parse_display_address("localhost:14158");
    EXPECT_EQ(local.host, "localhost");
    EXPECT_EQ(local.port, "14158");
    const DisplayAddress v6 = parse_display_address("[::1]:1");
    EXPECT_EQ(v6.host, "::1");
    EXPECT_EQ(v6.port, "1");
    EXPECT_EQ(parse_display_address("10.0.0.7:65535").host, "10.0.0.7");
    EXPECT_EQ(parse_display_address("render-box_2.lan:00080").port, "80");
    for (const char* bad : {"", "localhost", "localhost:", ":14158", "localhost:0", "localhost:65536",
                            "localhost:123456", "localhost:-1", "local host:1", "::1:14158", "[::1]", "a:b",
                            "localhost:14158 ", "host:1:2", "[]:1", "h\n:1"})
        EXPECT_THROW(parse_display_address(bad), UsageError) << bad;
}

}  // namespace
}  // namespace clr
