// BoundedServer (view/bounded_server.h) on its own, with a short write timeout: how it treats a
// client that reads an answer slowly.
#include <gtest/gtest.h>

#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>

#include "view/bounded_server.h"

namespace clr {
namespace {

// A client that reads a large answer slowly but steadily gets all of it, though the system calls
// the socket writable again only once a third of the send buffer is free, which at that pace
// takes longer than the write timeout: the answer is given up only when the client takes
// nothing for the write timeout (it was cut short after a third of a frame).
TEST(BoundedServer, ASlowButSteadyReaderGetsTheWholeAnswer) {
    BoundedServer server(2);
    server.set_write_timeout(0, 200 * 1000);  // 0.2 s
    const std::string big(std::size_t(6) << 20, 'x');
    server.Get("/big", [&](const httplib::Request&, httplib::Response& response) {
        response.set_content(big, "application/octet-stream");
    });
    const int port = server.bind_to_any_port("127.0.0.1");
    ASSERT_GT(port, 0);
    std::thread listener([&] { server.listen_after_bind(); });

    const int socket = ::socket(AF_INET, SOCK_STREAM, 0);
    int small = 64 * 1024;
    ::setsockopt(socket, SOL_SOCKET, SO_RCVBUF, &small, sizeof small);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ASSERT_EQ(::connect(socket, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
    const std::string request = "GET /big HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n";
    ASSERT_EQ(::send(socket, request.data(), request.size(), MSG_NOSIGNAL), static_cast<ssize_t>(request.size()));
    // 32 KiB every 20 ms: about 1.6 MB/s, 4 s for the answer; never a pause of 0.2 s.
    std::size_t received = 0;
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    char chunk[32 * 1024];
    while (std::chrono::steady_clock::now() < give_up) {
        pollfd ready{socket, POLLIN, 0};
        if (::poll(&ready, 1, 1000) <= 0) break;
        const ssize_t got = ::recv(socket, chunk, sizeof chunk, 0);
        if (got <= 0) break;
        received += static_cast<std::size_t>(got);
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ::close(socket);
    server.stop();
    listener.join();
    EXPECT_GT(received, big.size()) << "the head and all " << big.size() << " bytes of the body";
}

}  // namespace
}  // namespace clr
