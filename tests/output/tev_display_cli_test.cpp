// --display-server through the real binary (docs/command-line.md, Streaming to tev), with a
// stand-in tev (fake_tev_server.h): the image tev is sent is the written PNG's bytes decoded
// by the sRGB transfer function, frame after frame of an animation; a tev that is not running
// or goes away mid-render is one warning, and the files are written as without it.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cmath>
#include <string>

#include "output/fake_tev_server.h"
#include "scene/image_loader.h"
#include "support/command.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

using testing::FakeTevServer;
using testing::read_bytes;
using testing::run_clrender;
using testing::TempFolder;

const std::string kScene = R"({
  "eye": [0, 1, 8], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 50,
  "width": 40, "height": 30, "SunLocation": [10, 20, 10], "DefaultColor": [0.1, 0.2, 0.4],
  "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [0.9, 0.4, 0.2]},
              {"center": [2, 0.5, -1], "radius": 0.8, "ambient": [0.2, 0.8, 0.3]}]
})";

const std::string kAnimation = R"({
  "eyeLocations": [[-4, 1, 8], [4, 2, 7]], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 50,
  "width": 320, "height": 240, "clrender": {"frames": 6},
  "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [0.9, 0.4, 0.2]},
              {"center": [2, 0.5, -1], "radius": 0.8, "ambient": [0.2, 0.8, 0.3]}]
})";

double srgb_decoded(int byte) {  // IEC 61966-2-1
    const double v = byte / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

// Pixels of the tev image that are not the PNG's bytes decoded by the sRGB transfer function.
int pixels_unlike(const FakeTevServer::TevImage& tev, const Image& png) {
    if (tev.width != png.width || tev.height != png.height) return -1;
    const char* names[] = {"R", "G", "B"};
    int unlike = 0;
    for (int y = 0; y < png.height; ++y)
        for (int x = 0; x < png.width; ++x)
            for (int c = 0; c < 3; ++c)
                if (std::abs(tev.values.at(names[c])[y * png.width + x] - srgb_decoded(png.at(x, y, c))) > 1e-6) {
                    ++unlike;
                    break;
                }
    return unlike;
}

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

int warnings_in(const std::string& output) {
    int count = 0;
    for (std::size_t at = output.find("clrender: warning:"); at != std::string::npos;
         at = output.find("clrender: warning:", at + 1))
        ++count;
    return count;
}

TEST(TevDisplayCli, TevShowsTheWrittenStill) {
    TempFolder folder;
    folder.write("scene.json", kScene);
    FakeTevServer tev;
    const auto render = run_clrender("scene.json -q -o out.png --display-server " + tev.address(), folder.path());
    ASSERT_EQ(render.exit_code, 0) << render.output;
    EXPECT_EQ(warnings_in(render.output), 0) << render.output;
    const FakeTevServer::Received received = tev.wait();
    EXPECT_EQ(received.problem, "");
    ASSERT_EQ(received.images.count("scene"), 1u);
    const FakeTevServer::TevImage& image = received.images.at("scene");
    EXPECT_EQ(image.channels, (std::vector<std::string>{"R", "G", "B"}));
    EXPECT_EQ(pixels_unlike(image, *load_image(folder.file("out.png"))), 0);
}

TEST(TevDisplayCli, EachFrameOfAnAnimationReplacesTheLast) {
    TempFolder folder;
    folder.write("path.json", kAnimation);
    FakeTevServer tev;
    const auto render =
        run_clrender("path.json -q --size 40x30 -o 'f_%04d.png' --display-server " + tev.address(), folder.path());
    ASSERT_EQ(render.exit_code, 0) << render.output;
    const FakeTevServer::Received received = tev.wait();
    EXPECT_EQ(received.problem, "");
    ASSERT_EQ(received.images.count("path"), 1u);
    EXPECT_EQ(received.images.at("path").updates, 6);  // one packet a frame at this size
    EXPECT_EQ(pixels_unlike(received.images.at("path"), *load_image(folder.file("f_0005.png"))), 0);
    EXPECT_GT(pixels_unlike(received.images.at("path"), *load_image(folder.file("f_0000.png"))), 0);
}

TEST(TevDisplayCli, NoTevRunningIsAWarningAndTheSameImage) {
    TempFolder folder;
    folder.write("scene.json", kScene);
    const std::string address = "127.0.0.1:" + std::to_string(closed_port());
    const auto render = run_clrender("scene.json -q -o out.png --display-server " + address, folder.path());
    ASSERT_EQ(render.exit_code, 0) << render.output;
    EXPECT_EQ(warnings_in(render.output), 1) << render.output;
    EXPECT_NE(render.output.find("clrender: warning: --display-server " + address + ": cannot connect"),
              std::string::npos)
        << render.output;
    const auto plain = run_clrender("scene.json -q -o plain.png", folder.path());
    ASSERT_EQ(plain.exit_code, 0) << plain.output;
    EXPECT_EQ(read_bytes(folder.file("out.png")), read_bytes(folder.file("plain.png")));
}

// tev reads the CreateImage and the first frame, then closes: the render goes on to the last
// frame, with one warning.
TEST(TevDisplayCli, TevClosingMidRenderIsOneWarning) {
    TempFolder folder;
    folder.write("path.json", kAnimation);
    FakeTevServer tev(FakeTevServer::Behaviour::CloseEarly, 2);
    const auto render = run_clrender("path.json -q -o 'f_%04d.png' --display-server " + tev.address(), folder.path());
    ASSERT_EQ(render.exit_code, 0) << render.output;
    EXPECT_EQ(warnings_in(render.output), 1) << render.output;
    EXPECT_NE(render.output.find("the render goes on without the viewer"), std::string::npos) << render.output;
    for (int frame = 0; frame < 6; ++frame) EXPECT_EQ(load_image(folder.file(testing::frame_name(frame)))->width, 320);
}

TEST(TevDisplayCli, MalformedAddressesAreUsageErrors) {
    TempFolder folder;
    folder.write("scene.json", kScene);
    for (const char* address : {"localhost", "localhost:0", "localhost:70000", "''", "'a b:1'"}) {
        const auto render = run_clrender(std::string("scene.json -q --display-server ") + address, folder.path());
        EXPECT_EQ(render.exit_code, 1) << address << ": " << render.output;
        EXPECT_NE(render.output.find("clrender: error: "), std::string::npos) << render.output;
    }
    EXPECT_EQ(folder.entry_count(), 1);  // nothing written
}

}  // namespace
}  // namespace clr
