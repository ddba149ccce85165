// A TCP connection to a running tev image viewer, for its IPC packets (tev_packets.h). Every
// wait is bounded: connecting and each send give up after a timeout, so that a viewer that is
// not there, or that stops reading, never stalls a render (docs/command-line.md, Streaming to
// tev). Writing to a closed connection fails with an error, never a SIGPIPE.
#pragma once

#include <chrono>
#include <stdexcept>
#include <string>

#include "output/tev_packets.h"

namespace clr {

// Why the viewer cannot be reached or took no more data: one line.
class TevConnectionError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class TevConnection {
public:
    // Connects to `host` (a name, an IPv4 or an IPv6 address) at `port`, trying each address
    // the name resolves to, each for at most `timeout`. Throws TevConnectionError.
    TevConnection(const std::string& host, const std::string& port, std::chrono::milliseconds timeout);
    ~TevConnection();
    TevConnection(const TevConnection&) = delete;
    TevConnection& operator=(const TevConnection&) = delete;

    // Sends the whole packet. Throws TevConnectionError when the viewer closed the connection,
    // takes no data for the timeout, or a signal asks clrender to stop (core/interruption.h).
    void send(const TevPacket& packet);

private:
    int socket_ = -1;
    std::chrono::milliseconds timeout_;
};

}  // namespace clr
