// BoundedServer (view/bounded_server.h) on its own, with a short write timeout: how it treats a
// client that reads an answer slowly, a failed accept(), and answers on a kept-alive connection.
#include <gtest/gtest.h>

#include <dlfcn.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "support/loopback_client.h"
#include "view/bounded_server.h"

// accept() as cpp-httplib's library calls it (this definition comes before the C library's):
// the next `failing_accepts` calls fail with ENFILE, the system's file table full for a moment.
namespace {
std::atomic<int> failing_accepts{0};

bool accept_fails() {
    for (int left = failing_accepts; left > 0;)
        if (failing_accepts.compare_exchange_weak(left, left - 1)) {
            errno = ENFILE;
            return true;
        }
    return false;
}
}  // namespace

extern "C" int accept(int socket, sockaddr* address, socklen_t* length) {
    using Accept = int (*)(int, sockaddr*, socklen_t*);
    static const Accept real = reinterpret_cast<Accept>(::dlsym(RTLD_NEXT, "accept"));
    return accept_fails() ? -1 : real(socket, address, length);
}

extern "C" int accept4(int socket, sockaddr* address, socklen_t* length, int flags) {
    using Accept4 = int (*)(int, sockaddr*, socklen_t*, int);
    static const Accept4 real = reinterpret_cast<Accept4>(::dlsym(RTLD_NEXT, "accept4"));
    return accept_fails() ? -1 : real(socket, address, length, flags);
}

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

    const int socket = testing::connect_to_loopback(port, 64 * 1024);
    ASSERT_GE(socket, 0);
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

// cpp-httplib closes the listening socket at an accept() that fails with ENFILE (or ENOBUFS,
// ENOMEM) and returns: the viewer went on running with nothing listening, every client refused
// for good. listen_until_stopped() listens again on the same socket, whose connections waited.
TEST(BoundedServer, AFailedAcceptDoesNotEndTheListening) {
    BoundedServer server(2);
    server.Get("/hi", [](const httplib::Request&, httplib::Response& response) { response.set_content("hi", "text/plain"); });
    const int port = server.bind_to_any_port("127.0.0.1");
    ASSERT_GT(port, 0);
    std::thread listener([&] { server.listen_until_stopped(); });
    while (!server.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    httplib::Client client("127.0.0.1", port);
    client.set_connection_timeout(5);
    client.set_read_timeout(5);
    auto first = client.Get("/hi");
    ASSERT_TRUE(first);
    EXPECT_EQ(first->status, 200);

    failing_accepts = 1;
    for (int request = 0; request < 3; ++request) {
        httplib::Client next("127.0.0.1", port);
        next.set_connection_timeout(5);
        next.set_read_timeout(5);
        auto answer = next.Get("/hi");
        ASSERT_TRUE(answer) << "request " << request << " after the failed accept: " << httplib::to_string(answer.error());
        EXPECT_EQ(answer->status, 200);
        EXPECT_EQ(answer->body, "hi");
    }
    EXPECT_EQ(failing_accepts, 0) << "the accept() did not fail: the test tested nothing";

    // Stopped while every accept fails (rounds end one after another), the listening ends.
    failing_accepts = 1000000;
    const int socket = testing::connect_to_loopback(port);  // waits in the backlog
    ASSERT_GE(socket, 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
    const auto stopped_at = std::chrono::steady_clock::now();
    server.stop();
    listener.join();
    failing_accepts = 0;
    ::close(socket);
    EXPECT_LT(std::chrono::steady_clock::now() - stopped_at, std::chrono::seconds(2));
}

// Answers on a kept-alive connection leave at once. cpp-httplib writes an answer's head and its
// body apart; Nagle's algorithm held the body until the head was acknowledged, which the client's
// system delays by 40 ms: 20 small answers one after another took 0.8 s, each 40 ms.
TEST(BoundedServer, SmallAnswersOnAKeptAliveConnectionAreNotHeldBack) {
    BoundedServer server(2);
    server.set_keep_alive_max_count(100);  // as the viewer's (cpp-httplib's own is 5)
    server.Get("/hi", [](const httplib::Request&, httplib::Response& response) {
        response.set_content("hi", "text/plain");
    });
    const int port = server.bind_to_any_port("127.0.0.1");
    ASSERT_GT(port, 0);
    std::thread listener([&] { server.listen_after_bind(); });

    const int socket = testing::connect_to_loopback(port);
    ASSERT_GE(socket, 0);
    // One answer: its head and the two bytes of its body.
    const auto ask = [socket] {
        const std::string request = "GET /hi HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n";
        if (::send(socket, request.data(), request.size(), MSG_NOSIGNAL) != static_cast<ssize_t>(request.size()))
            return false;
        std::string answer;
        char chunk[4096];
        while (answer.find("\r\n\r\nhi") == std::string::npos) {
            pollfd ready{socket, POLLIN, 0};
            if (::poll(&ready, 1, 5000) <= 0) return false;
            const ssize_t got = ::recv(socket, chunk, sizeof chunk, 0);
            if (got <= 0) return false;
            answer.append(chunk, static_cast<std::size_t>(got));
        }
        return true;
    };
    // The connection's first answers are acknowledged at once anyway (TCP's quick start).
    bool answered = ask() && ask();
    const auto started = std::chrono::steady_clock::now();
    constexpr int kAnswers = 20;
    for (int k = 0; k < kAnswers && answered; ++k) answered = ask();
    const auto took = std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - started);
    ::close(socket);
    server.stop();
    listener.join();
    ASSERT_TRUE(answered);
    // 40 ms each before; a few milliseconds for all of them now (0.4 s leaves room for a busy machine).
    EXPECT_LT(took.count(), 400) << kAnswers << " answers took " << took.count() << " ms";
}


// Clients that send a request the server refuses (one it answers and closes, as the viewer's 403
// without the token; one whose head never ends, 408) and then neither read nor close: each
// refused connection lingered a tenth of a second in the thread that served it while others
// waited, so that 3200 requests without the token kept every other client waiting 10 s (and a
// client that went on sending them, for good). The linger is one thread's for all of them: a
// request that arrives whole behind 300 of them is answered at once.
TEST(BoundedServer, RefusedConnectionsThatLingerDoNotHoldTheThreads) {
    BoundedServer server(2);
    server.Get("/refused", [](const httplib::Request&, httplib::Response& response) {
        response.status = 403;
        response.set_header("Connection", "close");
    });
    server.Get("/hi", [](const httplib::Request&, httplib::Response& response) {
        response.set_content("hi", "text/plain");
    });
    const int port = server.bind_to_any_port("127.0.0.1");
    ASSERT_GT(port, 0);
    std::thread listener([&] { server.listen_after_bind(); });
    while (!server.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));

    constexpr int kRefused = 300;  // at 0.1 s of one of 2 threads each: 15 s
    std::vector<int> refused;
    for (int k = 0; k < kRefused; ++k) {
        const int socket = testing::connect_to_loopback(port);
        if (socket < 0) break;
        const std::string request = k % 2 == 0 ? "GET /refused HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n"
                                               : "GET /hi HTTP/1.1\r\nHost: 127.0.0.1\r\n";  // no end
        (void)::send(socket, request.data(), request.size(), MSG_NOSIGNAL);
        refused.push_back(socket);
    }
    const auto started = std::chrono::steady_clock::now();
    httplib::Client client("127.0.0.1", port);
    client.set_connection_timeout(60);
    client.set_read_timeout(60);
    const httplib::Result answer = client.Get("/hi");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    for (const int socket : refused) ::close(socket);
    server.stop();
    listener.join();
    EXPECT_EQ(refused.size(), std::size_t(kRefused));
    ASSERT_TRUE(answer);
    EXPECT_EQ(answer->status, 200);
    // The heads that never end take the two threads for their 1 s (kHeadWhileOthersWait); the
    // rest is the refusals' own work.
    EXPECT_LT(seconds, 6.0) << "s for a request behind " << kRefused << " refused connections";
}

// A refused connection still lingers: the server has shut its side (the client reads the answer
// to its end) but goes on reading and dropping what the client sends for up to kLingerTime, so
// that the client's late bytes do not make the system reset the connection, which can destroy
// the answer before the client reads it; after the linger the connection is closed, and bytes
// sent then are answered with a reset.
TEST(BoundedServer, ARefusedConnectionLingersThenCloses) {
    BoundedServer server(2);
    server.Get("/refused", [](const httplib::Request&, httplib::Response& response) {
        response.status = 403;
        response.set_header("Connection", "close");
    });
    const int port = server.bind_to_any_port("127.0.0.1");
    ASSERT_GT(port, 0);
    std::thread listener([&] { server.listen_after_bind(); });
    while (!server.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));

    const int socket = testing::connect_to_loopback(port);
    ASSERT_GE(socket, 0);
    const std::string request = "GET /refused HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n";
    ASSERT_EQ(::send(socket, request.data(), request.size(), MSG_NOSIGNAL), static_cast<ssize_t>(request.size()));
    std::string answer;
    char chunk[4096];
    for (;;) {
        pollfd ready{socket, POLLIN, 0};
        if (::poll(&ready, 1, 10000) <= 0) break;
        const ssize_t got = ::recv(socket, chunk, sizeof chunk, 0);
        if (got <= 0) break;  // the server's side shut after the answer
        answer.append(chunk, static_cast<std::size_t>(got));
    }
    const auto answered = std::chrono::steady_clock::now();
    EXPECT_EQ(answer.rfind("HTTP/1.1 403", 0), 0u) << answer;
    // Whether bytes sent now are taken: a reset from a closed connection fails the second send.
    const auto taken = [socket] {
        const std::string late(1024, 'x');
        bool sent = true;
        for (int k = 0; k < 2 && sent; ++k) {
            sent = ::send(socket, late.data(), late.size(), MSG_NOSIGNAL) == static_cast<ssize_t>(late.size());
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
        int error = 0;
        socklen_t length = sizeof error;
        ::getsockopt(socket, SOL_SOCKET, SO_ERROR, &error, &length);
        return sent && error == 0;
    };
    EXPECT_TRUE(taken()) << "bytes sent at once after the answer were met with a reset";
    EXPECT_LT(std::chrono::steady_clock::now() - answered, kLingerTime / 2) << "too slow to tell";
    std::this_thread::sleep_until(answered + 2 * kLingerTime + std::chrono::milliseconds(500));
    EXPECT_FALSE(taken()) << "the connection still open long after its linger";
    ::close(socket);
    server.stop();
    listener.join();
}

}  // namespace
}  // namespace clr
