// A request's connection found among the process's descriptors by its addresses, and seen to
// be gone once the client closes it.
#include "view/client_connection.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

namespace clr {
namespace {

int port_of(int socket, bool peer) {
    sockaddr_in address{};
    socklen_t length = sizeof address;
    if (peer)
        ::getpeername(socket, reinterpret_cast<sockaddr*>(&address), &length);
    else
        ::getsockname(socket, reinterpret_cast<sockaddr*>(&address), &length);
    return ntohs(address.sin_port);
}

// A listening socket on 127.0.0.1, a client connected to it and the server's end.
struct LoopbackPair {
    int listening = -1, client = -1, server = -1;
    LoopbackPair() {
        listening = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        if (::bind(listening, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 || ::listen(listening, 4) != 0)
            return;
        address.sin_port = htons(static_cast<std::uint16_t>(port_of(listening, false)));
        client = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
        if (::connect(client, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) return;
        server = ::accept4(listening, nullptr, nullptr, SOCK_CLOEXEC);
    }
    ~LoopbackPair() {
        for (int socket : {listening, client, server})
            if (socket >= 0) ::close(socket);
    }
};

TEST(ClientConnection, FindsTheServersEndAndSeesTheClientGo) {
    LoopbackPair pair;
    ASSERT_GE(pair.server, 0);
    const int server_port = port_of(pair.server, false), client_port = port_of(pair.server, true);
    const ClientConnection connection("127.0.0.1", server_port, "127.0.0.1", client_port);
    ASSERT_TRUE(connection.found());
    EXPECT_FALSE(connection.gone());
    // A client that sends the next request while it waits is still there.
    ASSERT_EQ(::write(pair.client, "GET / HTTP/1.1\r\n", 16), 16);
    EXPECT_FALSE(connection.gone());
    ::close(pair.client);
    pair.client = -1;
    EXPECT_TRUE(connection.gone());
}

TEST(ClientConnection, AnotherConnectionsAddressesFindNothing) {
    LoopbackPair pair;
    ASSERT_GE(pair.server, 0);
    const int server_port = port_of(pair.server, false), client_port = port_of(pair.server, true);
    for (const ClientConnection& other : {ClientConnection("127.0.0.1", server_port, "127.0.0.2", client_port),
                                          ClientConnection("127.0.0.1", server_port, "127.0.0.1", client_port + 1),
                                          ClientConnection("127.0.0.1", client_port, "127.0.0.1", server_port + 1),
                                          ClientConnection("", -1, "", -1)}) {
        EXPECT_FALSE(other.found());
        EXPECT_FALSE(other.gone());
    }
}

}  // namespace
}  // namespace clr
