#include "view/socket_address.h"

#include <netdb.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include <array>

namespace clr {
namespace {

std::optional<SocketAddress> numeric(const sockaddr_storage& address, socklen_t length) {
    SocketAddress named;
    if (address.ss_family == AF_INET)
        named.port = ntohs(reinterpret_cast<const sockaddr_in*>(&address)->sin_port);
    else if (address.ss_family == AF_INET6)
        named.port = ntohs(reinterpret_cast<const sockaddr_in6*>(&address)->sin6_port);
    else
        return std::nullopt;
    std::array<char, NI_MAXHOST> text{};
    if (::getnameinfo(reinterpret_cast<const sockaddr*>(&address), length, text.data(), text.size(), nullptr, 0,
                      NI_NUMERICHOST) != 0)
        return std::nullopt;
    named.ip = text.data();
    return named;
}

}  // namespace

std::optional<SocketAddress> local_address_of(int socket) {
    sockaddr_storage address{};
    socklen_t length = sizeof address;
    if (::getsockname(socket, reinterpret_cast<sockaddr*>(&address), &length) != 0) return std::nullopt;
    return numeric(address, length);
}

std::optional<SocketAddress> remote_address_of(int socket) {
    sockaddr_storage address{};
    socklen_t length = sizeof address;
    if (::getpeername(socket, reinterpret_cast<sockaddr*>(&address), &length) != 0) return std::nullopt;
    return numeric(address, length);
}

}  // namespace clr
