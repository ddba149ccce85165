// A stand-in for the tev image viewer in tests: a thread that listens on 127.0.0.1 (a free
// port), accepts one client and reads tev's IPC packets as tev's protocol defines them
// (tev's src/Ipc.cpp): parsed here on their own, byte by byte, not with clrender's packet
// code, and replayed into the images they describe.
#pragma once

#include <atomic>
#include <cstdint>
#include <map>
#include <string>
#include <thread>
#include <vector>

namespace clr::testing {

class FakeTevServer {
public:
    enum class Behaviour {
        Serve,          // read every packet until the client closes
        CloseEarly,     // close the connection after `packets` packets
        NeverRead,      // accept, then read nothing (a viewer that hangs)
    };
    explicit FakeTevServer(Behaviour behaviour = Behaviour::Serve, int packets = 0);
    ~FakeTevServer();
    FakeTevServer(const FakeTevServer&) = delete;
    FakeTevServer& operator=(const FakeTevServer&) = delete;

    int port() const { return port_; }
    std::string address() const { return "127.0.0.1:" + std::to_string(port_); }

    struct TevImage {
        int width = 0, height = 0;
        std::vector<std::string> channels;
        std::map<std::string, std::vector<float>> values;  // per channel, width * height, row by row
        int updates = 0;                                    // UpdateImage packets received for it
    };
    struct Received {
        std::vector<int> packet_types;
        std::map<std::string, TevImage> images;  // by name
        std::string problem;                     // a packet that does not follow the protocol
    };
    // Waits (at most 30 s) until the client closed the connection or the server closed it,
    // and returns what it received.
    Received wait();

private:
    void serve();
    void read_packets(int client);
    void apply(const std::vector<std::uint8_t>& packet);

    Behaviour behaviour_;
    int packets_allowed_;
    int listener_ = -1;
    int port_ = 0;
    std::atomic<bool> stop_{false};
    Received received_;
    std::thread thread_;
};

}  // namespace clr::testing
