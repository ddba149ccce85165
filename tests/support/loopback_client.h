// A plain TCP client socket on loopback, for tests that speak to a server byte by byte (a
// trickled head, a client that never reads) where an HTTP client library would not.
#pragma once

namespace clr::testing {

// A socket connected to 127.0.0.1:`port`; -1 when it cannot connect. With `receive_buffer`
// above 0, the socket's receive buffer is set that small before it connects.
int connect_to_loopback(int port, int receive_buffer = 0);

}  // namespace clr::testing
