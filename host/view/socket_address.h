// The two ends of a socket as numeric addresses ("127.0.0.1", "::1") and ports, written as
// cpp-httplib writes them into a request (ClientConnection finds a request's socket by them),
// and as the viewer names the address it listens on: the address actually bound, never a name.
#pragma once

#include <optional>
#include <string>

namespace clr {

struct SocketAddress {
    std::string ip;  // numeric, an IPv6 address without brackets
    int port = 0;
};

// This end of `socket` (for a listening socket: the address it listens on); nullopt where the
// system cannot say.
std::optional<SocketAddress> local_address_of(int socket);
// The other end of a connected `socket`.
std::optional<SocketAddress> remote_address_of(int socket);

}  // namespace clr
