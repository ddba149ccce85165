// Whether the client of a request is still there. cpp-httplib 0.11.4 gives a handler neither
// its socket nor a way to ask, so the socket is found among this process's descriptors by the
// request's two addresses (remote_addr:remote_port to local_addr:local_port): exactly one open
// connection has them, and it stays open while its request is handled. The viewer asks
// between the bands of a frame, so that a client that went away (a page that moved on, a
// closed tab) does not keep the device, and every client after it, waiting.
#pragma once

#include <string>

namespace clr {

class ClientConnection {
public:
    // The connection from `remote_addr`:`remote_port` to `local_addr`:`local_port` (numeric
    // addresses, as cpp-httplib gives them). When it cannot be found, gone() is always false.
    ClientConnection(const std::string& local_addr, int local_port, const std::string& remote_addr, int remote_port);

    bool found() const { return socket_ >= 0; }
    // Whether the client closed its side or the connection broke (it reads no answer now). A
    // client that only stopped sending (a half-close) counts as gone: until the server writes,
    // its end looks the same as a close (docs/robustness.md, Limits and what is left).
    bool gone() const;

private:
    int socket_ = -1;  // not owned: the server's
};

}  // namespace clr
